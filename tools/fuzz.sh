#!/usr/bin/env bash
# Builds the fuzzers of tests/fuzz/ with clang and libFuzzer (build-fuzz/,
# AddressSanitizer and UndefinedBehaviorSanitizer on) and runs each for
# SECONDS (default 60), starting from its seed corpus; new inputs that reach
# new code are kept in build-fuzz/corpus-NAME for the next run. A crash, a
# sanitizer report, a leak, an input slower than 10 s or one that needs more
# than 2 GB fails (exit 1), leaving the input in build-fuzz/ (crash-*,
# timeout-*, leak-*, oom-*) and libFuzzer's whole output in
# build-fuzz/fuzz_NAME.log: reproduce it with
#   build-fuzz/tests/fuzz/fuzz_NAME FILE
#   tools/fuzz.sh [SECONDS] [NAME...]     NAME: model_xml, journal, commands
#   tools/fuzz.sh --ci [NAME...]          what tools/test.sh (and so CI) runs:
#       a fixed number of inputs per target (15-25 s each on the 2-core
#       machine) from a fixed random seed, starting from the seed corpus
#       alone: the same work on any machine and mostly the same inputs
#       (coverage that depends on the clock can steer two runs apart).
# Each run ends with one line: executions, coverage (libFuzzer's cov: edges
# and ft: features) and the corpus size.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
ci=0
if [ "${1:-}" = --ci ]; then
  ci=1
  shift
  seconds=0
else
  seconds=${1:-60}
  shift || true
fi
# Inputs per target in a --ci run: ~7000, ~5000 and ~60 inputs a second.
declare -A ci_runs=([model_xml]=150000 [journal]=100000 [commands]=1500)
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(model_xml journal commands)
launcher=()
command -v ccache >/dev/null &&
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=Release -DTENDRIL_FUZZ=ON \
      -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_C_COMPILER=clang "${launcher[@]}" >/dev/null
cmake --build build-fuzz --parallel "$(nproc)" --target "${targets[@]/#/fuzz_}"
status=0
for name in "${targets[@]}"; do
  corpus=build-fuzz/corpus-$name
  log=build-fuzz/fuzz_$name.log
  if ((ci)); then
    corpus=build-fuzz/ci-corpus-$name
    rm -rf "$corpus"
    budget=(-runs="${ci_runs[$name]}" -seed=1)
    echo "fuzz_$name: ${ci_runs[$name]} inputs, seed 1"
  else
    budget=(-max_total_time="$seconds")
    echo "fuzz_$name: $seconds s"
  fi
  mkdir -p "$corpus"
  # One process (no -fork): a finding stops the run with a non-zero status.
  started=$SECONDS
  set +e
  (cd build-fuzz && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
     "tests/fuzz/fuzz_$name" "${corpus#build-fuzz/}" "../tests/fuzz/corpus/$name" \
     "${budget[@]}" -timeout=10 -rss_limit_mb=2048 -max_len=65536 -print_final_stats=1 \
     >"fuzz_$name.log" 2>&1)
  code=$?
  set -e
  grep -E "ERROR|SUMMARY|Test unit written|fuzz_$name: |==[0-9]+==" "$log" | head -40 || true
  done_line=$(grep -E "^#[0-9]+[[:space:]]+DONE" "$log" | tail -1 || true)
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  cov=$(grep -oE "cov: [0-9]+ ft: [0-9]+ corp: [0-9]+/[0-9]+[a-zA-Z]*" <<<"$done_line" || true)
  echo "fuzz_$name: ${runs:-?} executions in $((SECONDS - started)) s, ${cov:-no DONE line}"
  if [ "$code" -ne 0 ]; then
    echo "fuzz_$name found a fault (exit $code): see $log and $(ls build-fuzz/crash-* build-fuzz/timeout-* \
      build-fuzz/leak-* build-fuzz/oom-* 2>/dev/null | tr '\n' ' ')" >&2
    status=1
  fi
done
exit $status
