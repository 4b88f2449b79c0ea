#!/usr/bin/env bash
# setup.sh — install the Debian packages relcol needs (only the missing ones), then
# configure and build into $RELCOL_BUILD (default: build). Sourced by main-job.sh and
# test.sh; safe to run again (it does nothing that is already done).
set -euo pipefail

# mpi-default-dev and openmpi-bin come with libsundials-dev already; they are named
# because relcol-sweep's MPI build and its mpirun test use them directly. libhdf5-dev is
# the serial HDF5 of relcol-sim's H5MD trajectory; the python3 packages read its outputs in
# the tests (h5py: H5MD, ase: extended XYZ, numpy: CSV).
RELCOL_PACKAGES=(gcc libc6-dev meson ninja-build pkg-config libgsl-dev libsundials-dev
                 gnuplot-nox libcjson-dev mpi-default-dev openmpi-bin libhdf5-dev
                 python3-numpy python3-h5py python3-ase)

relcol_install_packages() {
    local missing=()
    for p in "${RELCOL_PACKAGES[@]}"; do
        dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" \
            || missing+=("$p")
    done
    if [ ${#missing[@]} -eq 0 ]; then
        return 0
    fi
    echo "relcol: installing missing Debian packages: ${missing[*]}" >&2
    local sudo=""
    if [ "$(id -u)" -ne 0 ]; then
        command -v sudo >/dev/null 2>&1 || {
            echo "relcol: need root (or sudo) to install: ${missing[*]}" >&2; return 1; }
        sudo="sudo"
    fi
    $sudo env DEBIAN_FRONTEND=noninteractive apt-get update -qq
    $sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
        "${missing[@]}" >/dev/null
}

# relcol_build DIR [meson setup options...]
relcol_build() {
    local dir="$1"; shift
    if [ ! -f "$dir/build.ninja" ]; then
        meson setup "$dir" "$@"
    fi
    meson compile -C "$dir"
}
