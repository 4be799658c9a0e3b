#!/usr/bin/env bash
# Installs what is missing (Debian packages, as root), then configures and
# builds tendril in ./build. Sourced by tools/run.sh and tools/test.sh.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

# clang and its runtime: the fuzzers of tests/fuzz (tools/fuzz.sh, libFuzzer).
# calculix-ccx: the independent FE solver of bench/fe and the test fe-ccx.
# python3-vtk9: VTK's own readers check tendril's VTK and glTF files (test vtk-python).
packages=(cmake g++ ninja-build pkg-config libeigen3-dev liblua5.4-dev lua5.4
          libcgal-dev libtinyxml2-dev libopenmesh-dev doctest-dev gnuplot-nox
          libcivetweb-dev nlohmann-json3-dev chromium libcli11-dev libtinygltf-dev
          slurm-wlm munge clang libclang-rt-14-dev calculix-ccx python3-vtk9)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# The studio page is built with Node.js and npm (Debian's, unless the machine has them).
command -v npm >/dev/null || missing+=(nodejs npm)
if ((${#missing[@]})); then
  echo "tendril: installing ${missing[*]}"
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${missing[@]}" >/dev/null
fi

# The studio page (web/): three.js, lil-gui, uPlot, vite and playwright-core
# from the npm registry at the versions of web/package-lock.json, built into
# web/dist; nothing is fetched when the page runs.
if [ ! -f web/node_modules/.package-lock.json ] || [ web/package-lock.json -nt web/node_modules/.package-lock.json ]; then
  (cd web && npm ci --no-audit --no-fund --loglevel=error)
fi
(cd web && npm run --silent build)

# ccache, when the machine has it, makes rebuilds after a checkout cheap.
launcher=()
command -v ccache >/dev/null &&
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" >/dev/null
cmake --build build --parallel "$(nproc)"
