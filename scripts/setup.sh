#!/usr/bin/env bash
# Installs pfdm's Debian dependencies (when missing) and builds Release into build/.
set -euo pipefail
cd "$(dirname "$0")/.."
packages=(cmake g++ make libceres-dev liblapack-dev libeigen3-dev libgoogle-glog-dev libgflags-dev
  libgtest-dev libgmock-dev libbenchmark-dev nlohmann-json3-dev libfccp-dev libnanoflann-dev
  libjemalloc-dev libnifti2-dev gnuplot-nox pybind11-dev python3-dev python3-numpy python3-pytest python3-matplotlib
  python3-pandas chromium)
# npm for report.html's three.js (report_js/); a Node.js from elsewhere
# (NodeSource's bundles npm) is kept: Debian's npm would conflict with it.
command -v npm > /dev/null || packages+=(nodejs npm)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo_cmd=""
  [ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"
  $sudo_cmd apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
# report.html's 3D view: three.js and esbuild at the versions
# report_js/package-lock.json pins (CMake bundles and inlines them).
npm ci --prefix report_js --no-audit --no-fund
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j "$(nproc)"
