#!/usr/bin/env bash
# Installs, builds, and runs the whole test suite (doctest binaries, every Lua
# scene under scripts/, every Lua example in the docs) through ctest.
#   tools/test.sh [CTEST ARGS]              the ordinary build, in build/
#   tools/test.sh --sanitize [CTEST ARGS]   a second build in build-sanitize/ with
#       AddressSanitizer, UndefinedBehaviorSanitizer and LeakSanitizer; any
#       report fails the test that caused it
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
if [ "${1:-}" = --sanitize ]; then
  shift
  cmake -S . -B build-sanitize -G Ninja -DCMAKE_BUILD_TYPE=Release -DTENDRIL_SANITIZE=ON "${launcher[@]}" >/dev/null
  cmake --build build-sanitize --parallel "$(nproc)"
  export ASAN_OPTIONS=detect_leaks=1:abort_on_error=0:detect_stack_use_after_return=0
  export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
  cd build-sanitize
else
  cd build
fi
ctest --output-on-failure --parallel "$(nproc)" "$@"
