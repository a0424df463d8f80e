#!/usr/bin/env bash
# Installs the Debian bookworm packages damseis needs (as root), if missing.
set -euo pipefail
packages=(
  cmake g++ make pkg-config
  libdolfinx-dev python3-ffcx libslepc-real-dev
  libgmsh-dev gmsh # gmsh: the example meshes' .geo files (tests remesh them)
  libtomlplusplus-dev libcli11-dev libeigen3-dev
  nlohmann-json3-dev libgtest-dev googletest
  libmumps-dev liblapack-dev libblas-dev # joint contact: MUMPS Schur complement, LAPACK, BLAS
  libfftw3-dev # response spectra, filters and artificial records (motion/)
  openmpi-bin
  libopenblas0-serial # MUMPS/Cholesky are 7-9x slower with reference BLAS
  python3-matplotlib python3-numpy python3-h5py
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" \
    || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "install-deps: installing ${missing[*]}"
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${missing[@]}"
fi
