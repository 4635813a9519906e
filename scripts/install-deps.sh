#!/usr/bin/env bash
# Installs the Debian 12 packages zdg needs, only those that are missing; runs
# `apt-get update` only when something is missing. Idempotent: a second run does nothing.
set -euo pipefail

packages=(
  build-essential cmake git pkg-config clang-format
  libgmp-dev libboost-dev libeigen3-dev libcgal-dev libmpfr-dev libspectra-dev libnanoflann-dev
  librapidcheck-dev libgtest-dev libbenchmark-dev
  libcli11-dev nlohmann-json3-dev libtomlplusplus-dev libfmt-dev pybind11-dev
  zlib1g-dev libnifti2-dev libpng-dev libsuitesparse-dev
  # .vdb volumes (kernel/io/vdb_io.cpp).
  libopenvdb-dev
  # `zdg transform dt|voronoi --mpi` (the MPI library and its launcher, mpiexec).
  libopenmpi-dev openmpi-bin
  # CHOLMOD's supernodal factorizations run in BLAS: OpenBLAS takes the libblas.so.3
  # alternative (the reference BLAS that libsuitesparse-dev pulls in is 7x slower here).
  libopenblas0-pthread
  python3 python3-dev python3-numpy python3-scipy python3-matplotlib python3-nibabel
  python3-pytest python3-hypothesis
)

# The test suite's own packages (the viewer pages are checked in headless Chromium; the example
# notebook runs in a Jupyter kernel through nbclient; an example reads a scikit-image sample;
# the persistence diagrams are compared with GUDHI's):
# installed by scripts/run-tests.sh (ZDG_TEST_PACKAGES=1), not by the main job.
if [ "${ZDG_TEST_PACKAGES:-0}" = 1 ]; then
  packages+=(chromium chromium-driver python3-selenium python3-nbclient python3-ipykernel
            python3-skimage python3-pydicom python3-gudhi)
fi

# Extra packages for one caller (CI adds the fuzzing toolchain: clang-14 libclang-rt-14-dev).
# shellcheck disable=SC2206
packages+=(${ZDG_EXTRA_PACKAGES:-})

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "install-deps: installing ${missing[*]}" >&2
sudo=()
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then
    sudo=(sudo)
  else
    echo "install-deps: missing packages (${missing[*]}) and neither root nor sudo" >&2
    exit 1
  fi
fi
"${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -qq
"${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
  "${missing[@]}"
