#!/usr/bin/env bash
# One-step set-up on Debian 12: installs the Debian packages rollerdyn needs (only those that
# are missing, so a second run costs nothing), then configures and builds it in Release under
# build/: the command line build/rollerdyn and the Python package build/python/rollerdyn (for
# /usr/bin/python3). Run as root (or with sudo available). Usage: bash scripts/setup.sh
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  cmake g++ make pkg-config
  libsimbody-dev        # multibody engine
  libeigen3-dev         # linear algebra of the reduced model and the analysis
  libsundials-dev       # CVODE, the reduced model's integrator
  libyaml-cpp-dev       # scene files
  nlohmann-json3-dev    # summary.json and friends
  libcli11-dev          # command line
  googletest libgtest-dev  # tests
  libbenchmark-dev      # Google Benchmark targets (benchmarks/)
  gnuplot-nox           # figures (PNG/SVG) of plot, report, bench and validation
  libjs-chart.js        # Chart.js, inlined into report.html for the interactive time plots
  chromium              # headless browser: the report page test (tests/report), scripts/check-report.sh
  libopenmpi-dev openmpi-bin  # sweeps over MPI ranks (mpirun/srun rollerdyn sweep) and their tests
  libnlopt-cxx-dev      # design optimization (rollerdyn optimize)
  # The Python module (src/python), built for Debian's /usr/bin/python3, its tests and the example
  # notebook (examples/), which the tests execute:
  pybind11-dev python3-pybind11 python3-dev
  python3-numpy python3-pandas python3-matplotlib
  python3-pytest python3-yaml   # tests of the Python module and of the examples in the docs
  jupyter-nbconvert python3-nbconvert python3-ipykernel
  jupyter-notebook      # to open the notebooks: PYTHONPATH=build/python jupyter notebook examples/
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)"
