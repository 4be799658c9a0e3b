#!/usr/bin/env bash
# Builds the benchmarks (Release, in ./build) and runs them, printing tables.
#
#   bench/run.sh [throughput|rule_cost|meshing|constraint_solvers|net|topology|low_rank|scaling] [options...]
#   bench/run.sh sweep [RUNS]
#   bench/run.sh fe [--param case=strip|ring|ring-p|net|frame] (tendril against CalculiX, bench/fe/fe.lua)
#   bench/run.sh hybrids   (textile hybrids with every integrator, bench/hybrids.lua)
#   bench/run.sh studio [SIZES [SECONDS]]   (e.g. 2000,20000,100000 5: the default)
#
# Without a selector every benchmark runs and the options go to the first two
# (e.g. --sizes 10K,100K); with one, only that benchmark runs and gets the
# options (e.g. `bench/run.sh rule_cost --apps 50`). See each binary's --help.
# The meshing benchmark compares paving with Debian's gmsh, installed here
# with apt-get when it is missing (benchmarks only: CI does not need it).
# `sweep` (only when asked for) measures a sweep's overhead per run, locally
# and on a one-node Slurm cluster it starts (bench/sweep.sh; needs root).
# `net` (only when asked for: minutes) times every integrator to equilibrium
# on the issue-18 net (bench/bench_net.cpp).
# `scaling` (only when asked for: minutes) times the static Newton solver
# (the benchmark's default choice; `auto`, tendril's default, takes the same
# steps here) to equilibrium on that net from 10K to 1M particles and fits the
# exponent (bench/bench_scaling.cpp; e.g. `bench/run.sh scaling --integrators
# newton,projective1 --sizes 10K,40K,160K`).
# `topology` (only when asked for) times one rule application and the step
# after it against a steady step, every integrator, on the same net
# (bench/bench_topology.cpp; e.g. `bench/run.sh topology --sizes 16384,100000,1M`,
# `--model beams` for a woven grid of spline beams, `beam6` for 6-DOF ones,
# `membrane` for the net as a CST membrane);
# `low_rank` why that change is followed by a Woodbury correction and not
# by conjugate gradients on the old factor (bench/bench_low_rank.cpp).
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build"
cd "$root"

benches=(throughput rule_cost meshing constraint_solvers)
selected=0 sweep=0
# The studio: a real server and a headless Chromium page (bench/studio_bench.mjs).
if [[ "${1:-}" == studio ]]; then
  shift
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$build" --target tendril
  (cd "$root/web" && npm run --silent build)
  exec node --experimental-websocket --no-warnings "$root/bench/studio_bench.mjs" "$@"
fi
# Textile hybrids with every integrator: steps, time, shape (bench/hybrids.lua).
if [[ "${1:-}" == hybrids ]]; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$build" --target tendril
  exec "$build/tendril" run "$root/bench/hybrids.lua" --quiet
fi
# tendril against CalculiX (issue 11): the same models in both, every node
# compared; needs ccx (Debian calculix-ccx), installed here when missing.
if [[ "${1:-}" == fe ]]; then
  shift
  if ! command -v ccx >/dev/null; then
    echo "bench/run.sh: installing calculix-ccx for the FE comparison" >&2
    sudo=()
    if [[ $(id -u) -ne 0 ]]; then sudo=(sudo); fi
    DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y calculix-ccx >/dev/null ||
      { "${sudo[@]}" apt-get update >/dev/null && DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y calculix-ccx >/dev/null; }
  fi
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$build" --target tendril
  exec "$build/tendril" run "$root/bench/fe/fe.lua" --out "$build/bench-fe" --quiet "$@"
fi
case "${1:-}" in
  sweep)
    benches=()
    sweep=1
    shift
    ;;
  throughput | rule_cost | meshing | constraint_solvers | net | topology | low_rank | scaling)
    benches=("$1")
    selected=1
    shift
    ;;
esac

if [[ " ${benches[*]} " == *" meshing "* ]] && ! command -v gmsh >/dev/null; then
  echo "bench/run.sh: installing gmsh for the meshing benchmark" >&2
  sudo=()
  if [[ $(id -u) -ne 0 ]]; then sudo=(sudo); fi
  export DEBIAN_FRONTEND=noninteractive
  if ! "${sudo[@]}" apt-get install -y gmsh >/dev/null 2>&1; then
    { "${sudo[@]}" apt-get update >/dev/null && "${sudo[@]}" apt-get install -y gmsh >/dev/null; } ||
      echo "bench/run.sh: could not install gmsh; its rows will read n/a" >&2
  fi
fi

generator=()
if [[ ! -f "$build/CMakeCache.txt" ]] && command -v ninja >/dev/null; then
  generator=(-G Ninja)
fi
cmake -S "$root" -B "$build" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release >/dev/null
if ((sweep)); then
  cmake --build "$build" --target tendril
  exec bash "$root/bench/sweep.sh" "$build/tendril" "$@"
fi
targets=()
for b in "${benches[@]}"; do targets+=("bench_$b"); done
cmake --build "$build" --target "${targets[@]}"

for b in "${benches[@]}"; do
  echo
  if [[ ($b == meshing || $b == constraint_solvers) && $selected -eq 0 ]]; then
    "$build/bench/bench_$b"
  else
    "$build/bench/bench_$b" "$@"
  fi
done
