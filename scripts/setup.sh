#!/usr/bin/env bash
# Installs the Debian 12 packages agglo needs to run (when missing) and builds, in Release into build/,
# what the showcase and the Python module need: the CLI `agglo` and the extension `_agglo`. The test
# suite's own packages and targets (GoogleTest, Google Benchmark, clang-tidy, Dask) come with
# scripts/test.sh, the README's second command.
set -euo pipefail
cd "$(dirname "$0")/.."
# shellcheck source=scripts/packages.sh
source scripts/packages.sh
install_missing $BUILD_PKGS
# The Python packages (mostly downloads) are installed while the build compiles.
py_log=$(mktemp)
install_missing $PY_PKGS >"$py_log" 2>&1 &
py_pid=$!
trap 'kill "$py_pid" 2>/dev/null || true; rm -f "$py_log"' EXIT
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DPython_EXECUTABLE=/usr/bin/python3 >/dev/null
cmake --build build -j"$(nproc)" --target agglo _agglo
if ! wait "$py_pid"; then
  cat "$py_log" >&2
  echo "setup: installing $PY_PKGS failed (output above)" >&2
  exit 1
fi
cat "$py_log"
# Make `import agglo` work for /usr/bin/python3: a .pth file in the site folder for local packages
# pointing at this build's module (docs/python.md).
site=$(/usr/bin/python3 -c 'import sys; print(f"/usr/local/lib/python3.{sys.version_info.minor}/dist-packages")')
pth="$site/agglo-build.pth"
if [ "$(cat "$pth" 2>/dev/null)" != "$PWD/build/python" ]; then
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO mkdir -p "$site"
  echo "$PWD/build/python" | $SUDO tee "$pth" >/dev/null
fi
