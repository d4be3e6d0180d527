#!/usr/bin/env bash
# The README's second command: installs the test suite's packages (when missing), builds every target
# of build/ (library, CLI, Python module, GoogleTest executables, benchmarks) and runs the whole suite
# with CTest on two cores. Extra arguments go to ctest (e.g. `-L dem`, `-R cli.`).
set -euo pipefail
cd "$(dirname "$0")/.."
# shellcheck source=scripts/packages.sh
source scripts/packages.sh
install_missing $RUN_PKGS $TEST_PKGS
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DPython_EXECUTABLE=/usr/bin/python3 >/dev/null
cmake --build build -j"$(nproc)"
ctest --test-dir build --output-on-failure -j2 "$@"
