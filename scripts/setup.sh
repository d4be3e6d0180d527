#!/usr/bin/env bash
# Installs the Debian 12 packages agglo needs (when missing) and builds it in Release into build/.
set -euo pipefail
cd "$(dirname "$0")/.."
PKGS="build-essential cmake pkg-config libeigen3-dev libtomlplusplus-dev libcli11-dev libfmt-dev
      nlohmann-json3-dev librandom123-dev libgtest-dev libbenchmark-dev python3-matplotlib python3-numpy
      clang-tidy libnetcdf-dev pybind11-dev python3-dev python3-pytest python3-xarray python3-netcdf4
      python3-distributed libopenmpi-dev openmpi-bin"
missing=""
for p in $PKGS; do dpkg -s "$p" >/dev/null 2>&1 || missing="$missing $p"; done
if [ -n "$missing" ]; then
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  echo "setup: installing$missing"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends $missing >/dev/null
fi
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DPython_EXECUTABLE=/usr/bin/python3 >/dev/null
cmake --build build -j"$(nproc)"
# Make `import agglo` work for /usr/bin/python3: a .pth file in the site folder for local packages
# pointing at this build's module (docs/python.md).
site=$(/usr/bin/python3 -c 'import sys; print(f"/usr/local/lib/python3.{sys.version_info.minor}/dist-packages")')
pth="$site/agglo-build.pth"
if [ "$(cat "$pth" 2>/dev/null)" != "$PWD/build/python" ]; then
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO mkdir -p "$site"
  echo "$PWD/build/python" | $SUDO tee "$pth" >/dev/null
fi
