#!/usr/bin/env bash
# Regenerates the examples' statecharts (src/statecharts/) from their models with `kse generate`.
# Hand-written activities in src/activities/ are never touched.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
"$here/../kse" generate --quiet "$here/Goalie/Goalie.stct" "$here/Attacker/Attacker.stct" \
  "$here/Defender/Defender.stct" "$here/src"
