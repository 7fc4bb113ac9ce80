#!/usr/bin/env bash
# The README's two commands:
#   bash .ci/quickstart.sh example   install what is missing, build, run prm/block_2d.prm
#   bash .ci/quickstart.sh test      install what is missing, build, run the test suite
# Works on a fresh Debian 12 or 13 machine (as root, or with sudo available).
set -euo pipefail
cd "$(dirname "$0")/.."

# what building and running the program needs; the suite needs the rest
build_packages="libdeal.ii-dev openmpi-bin cmake make g++"
# deal.II 9.6 (Debian 13) links with -fuse-ld=mold but only recommends mold;
# Debian 12's deal.II 9.4 uses the default linker
grep -qs '^VERSION_ID="12"' /etc/os-release || build_packages="$build_packages mold"
test_packages="numdiff perl jupyter-nbconvert python3-ipykernel python3-matplotlib python3-pandas python3-nbformat python3-meshio python3-h5py clang-format"

# install_missing PACKAGES...: install those not installed yet
install_missing() {
  local missing=""
  for p in "$@"; do
    dpkg -s "$p" > /dev/null 2>&1 || missing="$missing $p"
  done
  if [ -n "$missing" ]; then
    local sudo=""
    [ "$(id -u)" -eq 0 ] || sudo="sudo"
    echo "installing:$missing"
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends $missing < /dev/null
  fi
}

# build [TARGET [CMAKE-OPTION...]]: everything, or only TARGET (the example
# needs only the program, not the tutorial steps); the options are set in
# the build directory's cache, where they stay for later configures
build() {
  local target=${1:-}
  shift || true
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "$@" > /dev/null
  cmake --build build -j2 ${target:+--target "$target"}
}

# OpenMPI refuses to run as root unless told otherwise (CI runs as root)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

case "${1:-}" in
  example)
    install_missing $build_packages
    build hemicontact
    ./build/hemicontact prm/block_2d.prm
    echo "output written to $(pwd)/output-block-2d (open solution.pvd in ParaView)"
    ;;
  test)
    install_missing $build_packages $test_packages
    # the suite on, also in a build directory that 'example' configured
    # before numdiff was installed (its cache holds the suite off)
    build "" -DHEMICONTACT_WITH_TESTS=ON
    cd build
    # a suite that finds no test fails rather than passing empty
    ctest -j2 --output-on-failure --no-tests=error < /dev/null
    ;;
  *)
    echo "usage: bash .ci/quickstart.sh example|test" >&2
    exit 1
    ;;
esac
