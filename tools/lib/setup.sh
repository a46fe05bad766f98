# Shared set-up of tools/run and tools/test (sourced): installs the Debian packages that are
# missing (with sudo when not root), then configures and builds Release into build/.
set -euo pipefail
FOWTSIM_ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)

fowtsim_packages=(
  cmake ninja-build g++            # build
  libeigen3-dev libsundials-dev    # linear algebra, ODE integrators
  libhdf5-dev libyaml-cpp-dev      # outputs, input decks
  libfmt-dev libcli11-dev catch2   # formatting, command line, tests
  libfftw3-dev pkgconf             # FFT synthesis of irregular seas and turbulence
  python3-h5py python3-numpy       # proves outside tools read our HDF5 (regression tier)
  python3-matplotlib               # tools/plot (`fowtsim post --plot`): the plots engineers already read
  slurm-wlm munge                  # `fowtsim sweep --slurm` runs on a real single-node Slurm in the tests
)

fowtsim_install_missing_packages() {
  local missing=() p
  for p in "${fowtsim_packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  ((${#missing[@]} == 0)) && return 0
  local sudo=()
  [ "$(id -u)" -ne 0 ] && sudo=(sudo)
  echo "fowtsim: installing Debian packages: ${missing[*]}" >&2
  "${sudo[@]}" apt-get update -qq
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
}

fowtsim_build() {
  if [ ! -f "$FOWTSIM_ROOT/build/build.ninja" ]; then
    cmake -S "$FOWTSIM_ROOT" -B "$FOWTSIM_ROOT/build" -G Ninja -DCMAKE_BUILD_TYPE=Release >&2
  fi
  cmake --build "$FOWTSIM_ROOT/build" -j "$(nproc)" >&2
}

fowtsim_install_missing_packages
fowtsim_build
