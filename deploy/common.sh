# Shared by run.sh and test.sh: Debian 12 packages, and the CMake build in build/.
# Sourced, not executed. Idempotent: installs only what is missing, rebuilds only what changed.

set -euo pipefail

SAASGAPS_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
SAASGAPS_BUILD="${SAASGAPS_BUILD:-$SAASGAPS_ROOT/build}"

# What the build needs. libopenblas0-pthread takes over the libblas.so.3 alternative that CHOLMOD
# calls: the reference BLAS makes the supernodal factorization about 6x slower. libblas-dev: the
# CBLAS header and link name for the contact look-ahead's own dense products (sparse_cholesky.cpp).
BUILD_PACKAGES=(
  build-essential cmake pkg-config
  libeigen3-dev libsuitesparse-dev libblas-dev libopenblas0-pthread
  libcpp-httplib-dev nlohmann-json3-dev libsqlite3-dev libcli11-dev libcairo2-dev zlib1g-dev
  libgmsh-dev libexpat1-dev libseccomp-dev libsimdjson-dev rapidjson-dev
)
# What the README's examples use: the model generators in schemas/examples (python3) and the
# service walk-through (curl).
EXAMPLE_PACKAGES=(python3 curl)
# What the tests need on top.
TEST_PACKAGES=(googletest libgtest-dev python3-jsonschema python3-pil python3-meshio chromium chromium-driver calculix-ccx
  slurm-wlm munge)

# install_packages PKG...: apt-get installs the ones dpkg does not report as installed.
install_packages() {
  local missing=()
  for package in "$@"; do
    dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
  done
  if [ ${#missing[@]} -eq 0 ]; then
    return 0
  fi
  echo "installing: ${missing[*]}"
  local sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -qq
  $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

# build_project [TARGET...]: configure once, then build (all targets when none are named).
build_project() {
  if [ ! -f "$SAASGAPS_BUILD/CMakeCache.txt" ]; then
    cmake -S "$SAASGAPS_ROOT" -B "$SAASGAPS_BUILD" -DCMAKE_BUILD_TYPE=RelWithDebInfo
  fi
  local targets=()
  for target in "$@"; do targets+=(--target "$target"); done
  cmake --build "$SAASGAPS_BUILD" -j "$(nproc)" "${targets[@]}"
}
