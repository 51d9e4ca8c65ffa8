#!/usr/bin/env bash
# Regenerates the examples' statecharts (src/statecharts/) from their models with `kse generate`.
# Hand-written activities in src/activities/ are never touched.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
for model in Goalie Attacker Defender; do
  "$here/../kse" generate --quiet "$here/$model/$model.stct" "$here/src"
done
