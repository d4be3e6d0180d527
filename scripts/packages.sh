# The Debian 12 packages of agglo, declared once (sourced by scripts/setup.sh and scripts/test.sh;
# README "Building by hand" lists the same two groups).
# To build agglo and its Python module:
BUILD_PKGS="build-essential cmake ninja-build pkg-config libeigen3-dev libtomlplusplus-dev libcli11-dev libfmt-dev
  nlohmann-json3-dev librandom123-dev libnetcdf-dev libopenmpi-dev openmpi-bin pybind11-dev python3-dev"
# To run its plots and use its Python module (not needed to compile: scripts/setup.sh installs them
# while the build runs):
PY_PKGS="python3-numpy python3-matplotlib python3-xarray python3-netcdf4"
# Both: to build and run agglo, its plots and its Python module.
RUN_PKGS="$BUILD_PKGS $PY_PKGS"
# The build trees of scripts/setup.sh, scripts/test.sh and .ci/run are made with Ninja (package ninja-build
# above): it compiles a target's sources while the libraries it links are still being compiled, where
# Make waits for each library to be linked first (docs/timings.md). An existing build tree keeps its
# generator, and a CMAKE_GENERATOR set by the caller wins.
export CMAKE_GENERATOR="${CMAKE_GENERATOR:-Ninja}"
# Only for the test suite and the benchmarks (GoogleTest, Google Benchmark, the function-size lint,
# pytest, the Dask example's test, the notebooks; /usr/bin/time and column, which bench/ scripts and their
# smoke tests (ctest -L bench) use, are priority-optional packages a minimal Debian lacks; LAMMPS, binary
# lmp, for the bench/ scripts that compare agglo's DEM with it and their smoke tests):
TEST_PKGS="libgtest-dev libbenchmark-dev clang-tidy python3-pytest python3-distributed jupyter-nbconvert
  python3-ipykernel time bsdextrautils lammps"

# install_missing PKG...: apt-get installs the packages that dpkg does not know as installed (a package
# removed but not purged is known to `dpkg -s` with the status "deinstall ok config-files": not installed).
install_missing() {
  local missing="" p SUDO=""
  for p in "$@"; do
    [ "$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null)" = "install ok installed" ] || missing="$missing $p"
  done
  [ -n "$missing" ] || return 0
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  echo "setup: installing$missing"
  $SUDO apt-get update -qq
  # shellcheck disable=SC2086
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends $missing >/dev/null
}
