#!/usr/bin/env bash
# Installs, builds, and runs the whole test suite (doctest binaries, every Lua
# scene under scripts/, every Lua example in the docs) through ctest.
#   tools/test.sh                           the ordinary build, in build/, the
#       whole suite, then each fuzzer for 30 s from its seeds (tools/fuzz.sh;
#       a finding fails)
#   tools/test.sh CTEST ARGS                the ordinary build and the tests
#       the arguments select (e.g. -R studio), no fuzzers
#   tools/test.sh --sanitize [CTEST ARGS]   a second build in build-sanitize/ with
#       AddressSanitizer, UndefinedBehaviorSanitizer and LeakSanitizer; any
#       report fails the test that caused it
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
sanitize=0
if [ "${1:-}" = --sanitize ]; then
  sanitize=1
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
# The whole ordinary suite goes on with the fuzzers, briefly (CI: .ci/run).
if [ $# -eq 0 ] && [ $sanitize -eq 0 ]; then
  bash ../tools/fuzz.sh 30
fi
