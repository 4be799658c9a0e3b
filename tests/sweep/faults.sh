#!/usr/bin/env bash
# Fault tests of tendril sweep (issues 13 and 16), on local processes:
#
#   faults.sh TENDRIL WORK PART
#   PART: kill-resume  SIGKILL to the sweep half-way, then --resume: the same
#                      sweep.csv and model files as a sweep never interrupted
#         failing-run  a scene error on one seed is one row with its error;
#                      the others run; exit status 1
#         signal       SIGTERM to the sweep reaches its running runs: none is
#                      left behind, each is marked cancelled, exit 128+15
set -u
tendril=$1 work=$2 part=$3
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
scene=$here/chain.lua
mkdir -p "$work"
work=$(cd "$work" && pwd)
cd "$work"

fail() { echo "FAIL: $*" >&2; exit 1; }
note() { echo "$*"; }

# Processes whose command line names the folder (a run or a sweep in it).
left_in() {
  local p
  for p in /proc/[0-9]*; do
    [ "$p" = "/proc/$$" ] && continue
    tr '\0' ' ' <"$p/cmdline" 2>/dev/null | grep -F -- "$1/" | sed "s|^|${p#/proc/}: |"
  done
  return 0
}

count() { find "$1" -mindepth 2 -maxdepth 2 -name "$2" 2>/dev/null | wc -l; }

# Waits until N run folders of DIR hold FILE, at most SECONDS.
await() {
  local dir=$1 file=$2 n=$3 seconds=$4 waited=0
  until [ "$(count "$dir" "$file")" -ge "$n" ]; do
    sleep 0.05; waited=$((waited + 1))
    [ $waited -lt $((20 * seconds)) ] || fail "not $n runs of $dir with $file within $seconds s"
  done
}

kill_resume() {
  local args=(sweep "$scene" --param segments=12,24 --seeds 1..4 --param hold=0.15 --jobs 2)
  rm -rf whole killed
  "$tendril" "${args[@]}" --out whole >/dev/null 2>whole.stderr || fail "the uninterrupted sweep failed: $(cat whole.stderr)"
  "$tendril" "${args[@]}" --out killed >/dev/null 2>killed.stderr &
  local pid=$!
  await killed done 3 60
  kill -KILL $pid
  wait $pid 2>/dev/null
  local done_before; done_before=$(count killed done)
  [ "$done_before" -lt 8 ] || fail "the sweep had finished before the kill"
  # The runs die with their sweep (PR_SET_PDEATHSIG): none is left running.
  sleep 0.5
  [ -z "$(left_in "$work/killed")" ] || fail "runs left running after SIGKILL: $(left_in "$work/killed")"
  [ -f killed/sweep.csv ] || fail "no sweep.csv: rows are not written as runs finish"
  local rows; rows=$(($(wc -l <killed/sweep.csv) - 1))
  [ "$rows" -ge 1 ] || fail "sweep.csv has no rows after $done_before runs finished"
  "$tendril" "${args[@]}" --out killed >/dev/null 2>killed.again && fail "a second run without --resume was not refused"
  grep -q "finished runs of this sweep: --resume continues it" killed.again || fail "$(cat killed.again)"
  "$tendril" "${args[@]}" --out killed --resume >/dev/null 2>killed.resume || fail "--resume failed: $(cat killed.resume)"
  grep -q "resuming .*: $done_before of 8 runs finished" killed.resume || fail "resume: $(cat killed.resume)"
  cmp whole/sweep.csv killed/sweep.csv || fail "sweep.csv after kill and resume differs from the uninterrupted one"
  cmp whole/summary.md killed/summary.md || fail "summary.md differs"
  local k
  for k in 1 2 3 4 5 6 7 8; do
    cmp whole/run-$k/chain.xml killed/run-$k/chain.xml || fail "run $k: chain.xml differs"
  done
  grep -q '"chain, 12 cables"' whole/sweep.csv || fail "the label with a comma is not quoted in sweep.csv"
  note "kill-resume: SIGKILL after $done_before of 8 runs ($rows rows in sweep.csv), no run left running;" \
    "--resume ran the rest: sweep.csv, summary.md and every chain.xml identical to the uninterrupted sweep"
}

failing_run() {
  rm -rf failing
  "$tendril" sweep "$scene" --param fail_seed=2 --seeds 1..3 --jobs 2 --out failing >failing.stdout 2>failing.stderr
  local status=$?
  [ "$status" -eq 1 ] || fail "exit status $status, expected 1"
  [ "$(wc -l <failing/sweep.csv)" -eq 4 ] || fail "sweep.csv: $(cat failing/sweep.csv)"
  grep -q "^1,2,1,ok," failing/sweep.csv || fail "run 1: $(cat failing/sweep.csv)"
  grep -q "^3,2,3,ok," failing/sweep.csv || fail "run 3: $(cat failing/sweep.csv)"
  grep -Eq "^2,2,2,failed,.*chain.lua:[0-9]+: seed 2 fails on purpose$" failing/sweep.csv ||
    fail "run 2 is not a row with its error: $(cat failing/sweep.csv)"
  grep -q "| 2 | 2 | 2 | failed | .*seed 2 fails on purpose |" failing/summary.md || fail "summary.md: $(cat failing/summary.md)"
  grep -q "3 runs: 2 ok, 1 failed" failing.stdout || fail "$(cat failing.stdout)"
  note "failing-run: exit 1; $(grep '^2,' failing/sweep.csv)"
}

signal() {
  rm -rf signalled
  touch hold
  "$tendril" sweep "$scene" --param hold_while="$work/hold" --seeds 1..4 --jobs 2 --out signalled >/dev/null 2>signal.stderr &
  local pid=$!
  await signalled summary.csv 2 30
  kill -TERM $pid
  wait $pid; local status=$?
  rm -f hold
  [ "$status" -eq 143 ] || fail "exit status $status, expected 143 (SIGTERM)"
  [ -z "$(left_in "$work/signalled")" ] || fail "runs left running after SIGTERM: $(left_in "$work/signalled")"
  [ "$(count signalled cancelled)" -eq 2 ] || fail "$(count signalled cancelled) runs marked cancelled, expected 2"
  [ "$(count signalled done)" -eq 0 ] || fail "a run held by the file is marked done"
  grep -q "^1,[^,]*,1,cancelled,cancelled by SIGTERM$" signalled/sweep.csv || fail "sweep.csv: $(cat signalled/sweep.csv)"
  grep -q "^3,[^,]*,3,pending,$" signalled/sweep.csv || fail "sweep.csv: $(cat signalled/sweep.csv)"
  note "signal: SIGTERM forwarded to the 2 running runs, both cancelled, none left; exit 143;" \
    "$(grep -c ',cancelled,' signalled/sweep.csv) cancelled and $(grep -c ',pending,' signalled/sweep.csv) pending rows"
}

case $part in
  kill-resume) kill_resume ;;
  failing-run) failing_run ;;
  signal) signal ;;
  *) fail "unknown part $part" ;;
esac
echo "ok: $part"
