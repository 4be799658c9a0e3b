#!/usr/bin/env bash
# Builds the fuzzers of tests/fuzz/ with clang and libFuzzer (build-fuzz/,
# AddressSanitizer and UndefinedBehaviorSanitizer on) and runs each for
# SECONDS (default 60), starting from its seed corpus; new inputs that reach
# new code are kept in build-fuzz/corpus-NAME for the next run. A crash, a
# sanitizer report, a leak or an input slower than 10 s fails, leaving the
# input in build-fuzz/ (crash-*, timeout-*, leak-*): reproduce it with
#   build-fuzz/tests/fuzz/fuzz_NAME FILE
#   tools/fuzz.sh [SECONDS] [NAME...]     NAME: model_xml, journal
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
seconds=${1:-60}
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(model_xml journal)
launcher=()
command -v ccache >/dev/null &&
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=Release -DTENDRIL_FUZZ=ON \
      -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_C_COMPILER=clang "${launcher[@]}" >/dev/null
cmake --build build-fuzz --parallel "$(nproc)" --target "${targets[@]/#/fuzz_}"
for name in "${targets[@]}"; do
  corpus=build-fuzz/corpus-$name
  mkdir -p "$corpus"
  echo "fuzz_$name: $seconds s"
  (cd build-fuzz && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
     "tests/fuzz/fuzz_$name" "corpus-$name" "../tests/fuzz/corpus/$name" \
     -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=65536 -print_final_stats=1 2>&1 |
     grep -E "^#[0-9]+ +(INITED|DONE)|^stat::(number_of_executed_units|peak_rss_mb)|ERROR|SUMMARY|Test unit written|^cov|==[0-9]+==" || true)
  # libFuzzer's exit status is lost in the pipe: a finding leaves its file.
  if compgen -G "build-fuzz/crash-*" >/dev/null || compgen -G "build-fuzz/timeout-*" >/dev/null ||
     compgen -G "build-fuzz/leak-*" >/dev/null || compgen -G "build-fuzz/oom-*" >/dev/null; then
    echo "fuzz_$name found a fault: $(ls build-fuzz/crash-* build-fuzz/timeout-* build-fuzz/leak-* build-fuzz/oom-* 2>/dev/null)" >&2
    exit 1
  fi
done
