#!/usr/bin/env bash
# Builds the benchmarks (Release, in ./build) and runs them, printing tables.
#
#   bench/run.sh [throughput|rule_cost] [options...]
#
# Without a selector both benchmarks run and every option goes to both (e.g.
# --sizes 10K,100K); with one, only that benchmark runs and gets the options
# (e.g. `bench/run.sh rule_cost --apps 50`). See each binary's --help.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build"
cd "$root"

benches=(throughput rule_cost)
case "${1:-}" in
  throughput | rule_cost)
    benches=("$1")
    shift
    ;;
esac

generator=()
if [[ ! -f "$build/CMakeCache.txt" ]] && command -v ninja >/dev/null; then
  generator=(-G Ninja)
fi
cmake -S "$root" -B "$build" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release >/dev/null
targets=()
for b in "${benches[@]}"; do targets+=("bench_$b"); done
cmake --build "$build" --target "${targets[@]}"

for b in "${benches[@]}"; do
  echo
  "$build/bench/bench_$b" "$@"
done
