#!/usr/bin/env bash
# tendril sweep on a real one-node Slurm cluster started here
# (tools/slurm_cluster.sh: munged, slurmctld and slurmd on localhost):
#
#   slurm.sh TENDRIL WORK
#
# 1. The default scene (scripts/examples/grow.lua), 2 x 3 runs, submitted as
#    a job array and gathered, against the same sweep run locally: sweep.csv,
#    summary.md and every run's model database, journal and summary
#    byte-identical.
# 2. A task cancelled with scancel while it runs is reported as cancelled by
#    --gather, and `--resume --slurm` reruns it alone; the sweep then equals
#    a local one.
# Exits 77 (skipped) with the reason when the cluster cannot start here.
set -u
tendril=$1 work=$2
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)
mkdir -p "$work"
work=$(cd "$work" && pwd)
cd "$work"

fail() { echo "FAIL: $*" >&2; exit 1; }
note() { echo "$*"; }

source "$root/tools/slurm_cluster.sh"
if ! slurm_start "$work/cluster"; then
  echo "skipped: no Slurm cluster here: $slurm_why"
  exit 77
fi
trap 'slurm_stop "$work/cluster"' EXIT
note "cluster up: $(sinfo --noheader --format='%P %D node(s), %c cores, %T')"

same_sweeps() {
  local a=$1 b=$2 k f
  cmp "$a/sweep.csv" "$b/sweep.csv" || fail "sweep.csv: $a and $b differ"
  cmp "$a/summary.md" "$b/summary.md" || fail "summary.md: $a and $b differ"
  for k in $(seq 1 "$(($(wc -l <"$a/plan.csv") - 1))"); do
    for f in "$a/run-$k"/*.xml "$a/run-$k"/journal.txt "$a/run-$k"/summary.csv; do
      [ -e "$f" ] || continue
      cmp "$f" "$b/run-$k/$(basename "$f")" || fail "run $k: $(basename "$f") differs between $a and $b"
    done
  done
}

# 1. grow.lua, 2 x 3
grow=(sweep "$root/scripts/examples/grow.lua" --param view=35,60 --seeds 1..3)
rm -rf local slurm
"$tendril" "${grow[@]}" --jobs 2 --out local >local.stdout 2>local.stderr || fail "local sweep: $(cat local.stderr)"
start=$(date +%s%N)
"$tendril" "${grow[@]}" --slurm --out slurm >slurm.stdout 2>slurm.stderr || fail "Slurm sweep: $(cat slurm.stderr)"
elapsed=$(( ($(date +%s%N) - start) / 1000000 ))
grep -q "submitted Slurm job" slurm.stderr || fail "$(cat slurm.stderr)"
[ "$(ls slurm/slurm/task-*.out | wc -l)" -eq 6 ] || fail "not 6 array tasks: $(ls slurm/slurm)"
grep -q "6 runs: 6 ok" slurm.stdout || fail "$(cat slurm.stdout)"
same_sweeps local slurm
note "grow.lua 2 x 3: job array of 6 tasks in $elapsed ms; sweep.csv, summary.md and every grow.xml," \
  "journal.txt and summary.csv identical to the local sweep"
"$tendril" sweep --gather slurm >/dev/null 2>&1 || fail "--gather of a finished sweep failed"
cmp local/sweep.csv slurm/sweep.csv || fail "--gather changed sweep.csv"

# 2. a task cancelled while it runs
chain=(sweep "$root/tests/sweep/chain.lua" --seeds 1..3 --param hold_while="$work/hold" --param hold_seed=2)
rm -rf cancel cancel-local hold
touch hold
"$tendril" "${chain[@]}" --slurm --no-wait --out cancel >cancel.stdout 2>cancel.stderr || fail "$(cat cancel.stderr)"
job=$(cat cancel.stdout)
waited=0
until [ -f cancel/run-2/summary.csv ] && [ -f cancel/run-1/done ] && [ -f cancel/run-3/done ]; do
  sleep 0.2; waited=$((waited + 1))
  [ $waited -lt 300 ] || fail "the tasks did not run within 60 s: $(squeue --noheader --array --jobs="$job")"
done
scancel "${job}_2"
waited=0
while squeue --noheader --array --jobs="$job" --format=%T 2>/dev/null | grep -q -E 'PENDING|RUNNING|COMPLETING'; do
  sleep 0.2; waited=$((waited + 1))
  [ $waited -lt 300 ] || fail "task 2 was not cancelled within 60 s"
done
rm -f hold
"$tendril" sweep --gather cancel >gather.stdout 2>gather.stderr && fail "--gather of a sweep with a cancelled run exits 0"
grep -q "^2,[^,]*,2,2,cancelled,.*,cancelled by SIGTERM$" cancel/sweep.csv || fail "sweep.csv: $(cat cancel/sweep.csv)"
grep -q "3 runs: 2 ok, 0 failed, 1 cancelled" gather.stdout || fail "$(cat gather.stdout)"
[ -f cancel/run-2/cancelled ] && [ ! -f cancel/run-2/done ] || fail "run 2 is not marked cancelled: $(ls cancel/run-2)"
cancelled_row=$(grep '^2,' cancel/sweep.csv)
"$tendril" "${chain[@]}" --slurm --resume --out cancel >resume.stdout 2>resume.stderr || fail "resume: $(cat resume.stderr)"
grep -q "resuming .*: 2 of 3 runs finished, 1 to run" resume.stderr || fail "$(cat resume.stderr)"
grep -q "^#SBATCH --array=2$" cancel/slurm/array.sh || fail "the resumed array is not task 2 alone: $(cat cancel/slurm/array.sh)"
"$tendril" "${chain[@]}" --jobs 2 --out cancel-local >/dev/null 2>&1 || fail "the local chain sweep failed"
same_sweeps cancel-local cancel
note "cancelled task: '$cancelled_row'; --gather exits 1; --resume --slurm submitted --array=2 only;" \
  "then sweep.csv, summary.md and every chain.xml identical to a local sweep"
echo "ok: slurm"
