#!/usr/bin/env bash
# The cost of a sweep's machinery per run: RUNS runs of a small scene
# (tests/sweep/chain.lua, tens of milliseconds each) run directly one after
# the other, as a local sweep with --jobs 2, and as a job array on a
# one-node Slurm cluster started here (tools/slurm_cluster.sh; needs root).
#
#   bench/sweep.sh TENDRIL [RUNS]      (bash bench/run.sh sweep [RUNS])
#
# overhead per run = slots x wall time / runs - the mean time of a run
# (times.csv): the slot time each run costs beyond its own process.
set -u
tendril=$1 runs=${2:-200}
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
scene=$root/tests/sweep/chain.lua
work=$(mktemp -d /tmp/tendril-bench-sweep-XXXXXX)
trap 'rm -rf "$work"' EXIT
seeds=$((runs / 4))
plan=(--param segments=8,12,16,20 --seeds "1..$seeds")
runs=$((4 * seeds))

now_ms() { echo $(($(date +%s%N) / 1000000)); }
mean_run_ms() { awk -F, 'NR > 1 { s += $3; n++ } END { printf "%.1f", 1000 * s / n }' "$1/times.csv"; }
row() { # label slots wall_ms dir
  local mean; mean=$(mean_run_ms "$4")
  awk -v l="$1" -v s="$2" -v w="$3" -v m="$mean" -v n="$runs" \
    'BEGIN { printf "%-34s %5d %10.0f %12.1f %15.1f\n", l, s, w, m, s * w / n - m }'
}

echo "sweep overhead: $runs runs of tests/sweep/chain.lua on $(nproc) cores (load average $(cut -d' ' -f1-3 /proc/loadavg))"
printf "%-34s %5s %10s %12s %15s\n" "how" "slots" "wall ms" "run mean ms" "overhead/run ms"

start=$(now_ms)
for s in $(seq 1 "$seeds"); do
  for n in 8 12 16 20; do "$tendril" run "$scene" --quiet --seed "$s" --param segments=$n --out "$work/direct" >/dev/null; done
done
direct=$(($(now_ms) - start))
awk -v w="$direct" -v n="$runs" 'BEGIN { printf "%-34s %5d %10.0f %12.1f %15s\n", "tendril run, one after the other", 1, w, w / n, "-" }'

start=$(now_ms)
"$tendril" sweep "$scene" "${plan[@]}" --jobs 2 --out "$work/local" >/dev/null 2>&1 || echo "the local sweep failed"
row "tendril sweep --jobs 2" 2 $(($(now_ms) - start)) "$work/local"

source "$root/tools/slurm_cluster.sh"
if slurm_start "$work/cluster"; then
  start=$(now_ms)
  "$tendril" sweep "$scene" "${plan[@]}" --slurm --out "$work/slurm" >/dev/null 2>&1 || echo "the Slurm sweep failed"
  row "tendril sweep --slurm (1 node)" "$(nproc)" $(($(now_ms) - start)) "$work/slurm"
  cmp -s "$work/local/sweep.csv" "$work/slurm/sweep.csv" && echo "sweep.csv: local and Slurm identical" ||
    echo "sweep.csv: local and Slurm DIFFER"
  slurm_stop "$work/cluster"
else
  echo "Slurm: not measured ($slurm_why)"
fi
