#!/usr/bin/env bash
# kse lsp under a real LSP client (editors/vscode/test: vscode-languageserver-protocol starts the
# repository's ./kse lsp, opens formula files and statecharts, checks problems with their line and
# column, completion, go to definition, hover and symbols), then the VS Code extension packaged
# into editors/vscode/kse-<version>.vsix. Needs the launcher built (./kse builds it when missing).
set -euo pipefail
cd "$(dirname "$0")/../../editors/vscode"
npm ci --no-audit --no-fund --loglevel=error --prefer-offline
KSE_COMMAND="${KSE_COMMAND:-$PWD/../../kse}" node --test test/
log=$(mktemp)
trap 'rm -f "$log"' EXIT
npm run --silent package > "$log" 2>&1 || { cat "$log"; exit 1; }
echo "   packaged editors/vscode/$(ls kse-*.vsix)"
