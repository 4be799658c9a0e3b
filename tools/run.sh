#!/usr/bin/env bash
# Installs, builds, and runs the main job: the default scene, outputs in out/.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
./build/tendril run "${1:-scripts/examples/grow.lua}" --out out
echo "tendril: outputs in $(pwd)/out"
ls -l out
