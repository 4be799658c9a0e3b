#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test: what CI runs.
#   tools/test.sh                the three phases below, each timed:
#     1. the ordinary build (build/): the whole suite through ctest - the
#        doctest binaries, every Lua scene under scripts/, every Lua example
#        in the docs, the browser, Slurm, CalculiX and fault tests;
#     2. a clang build with AddressSanitizer, UndefinedBehaviorSanitizer and
#        LeakSanitizer (build-sanitize/): the same suite again; any report
#        fails the test that caused it;
#     3. the fuzzers (tools/fuzz.sh --ci): each from its seed corpus, for a
#        fixed number of inputs from a fixed seed.
#   tools/test.sh CTEST ARGS                phase 1 only, the tests selected (e.g. -R studio)
#   tools/test.sh --sanitize [CTEST ARGS]   phase 2 only
#   tools/test.sh --fuzz                    phase 3 only
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"

ordinary() {
  (cd build && ctest --output-on-failure --parallel "$(nproc)" "$@")
}

sanitized() {
  # clang: its instrumented build costs about a third of gcc's here.
  CC=clang CXX=clang++ cmake -S . -B build-sanitize -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DTENDRIL_SANITIZE=ON "${launcher[@]}" >/dev/null
  cmake --build build-sanitize --parallel "$(nproc)"
  (cd build-sanitize &&
     ASAN_OPTIONS=detect_leaks=1:abort_on_error=0:detect_stack_use_after_return=0 \
     UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
     ctest --output-on-failure --parallel "$(nproc)" "$@")
}

timed() {
  local name=$1 start=$SECONDS
  shift
  "$@"
  echo "tools/test.sh: $name: $((SECONDS - start)) s"
}

case "${1:-}" in
  --sanitize) shift; timed "sanitized suite" sanitized "$@" ;;
  --fuzz) timed fuzzers bash tools/fuzz.sh --ci ;;
  "")
    timed "ordinary suite" ordinary
    timed "sanitized suite" sanitized
    timed fuzzers bash tools/fuzz.sh --ci
    ;;
  *) timed "ordinary suite" ordinary "$@" ;;
esac
