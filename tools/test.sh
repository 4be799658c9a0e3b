#!/usr/bin/env bash
# Installs, builds, and runs the whole test suite (doctest binaries, every Lua
# scene under scripts/, every Lua example in the docs) through ctest.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
cd build
ctest --output-on-failure --parallel "$(nproc)" "$@"
