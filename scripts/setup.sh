#!/usr/bin/env bash
# setup.sh — install the Debian packages relcol needs (only the missing ones), then
# configure and build into $RELCOL_BUILD (default: build). Sourced by main-job.sh and
# test.sh; safe to run again (it does nothing that is already done).
set -euo pipefail

# mpi-default-dev and openmpi-bin come with libsundials-dev already; they are named
# because relcol-sweep's MPI build and its mpirun test use them directly. libhdf5-dev is
# the serial HDF5 of relcol-sim's H5MD trajectory; the python3 packages read its outputs in
# the tests (h5py and mdanalysis: H5MD, ase: extended XYZ, numpy: CSV). strace: the publish
# test's fault injection (tests/sim/test_sim_publish.sh fails each system call of a run in turn).
RELCOL_PACKAGES=(gcc libc6-dev meson ninja-build pkg-config libgsl-dev libsundials-dev
                 gnuplot-nox libcjson-dev mpi-default-dev openmpi-bin help2man libhdf5-dev
                 python3-numpy python3-h5py python3-ase python3-mdanalysis strace)
# The Python package (python/, meson option -Dpython): its build needs cffi, numpy and the
# Python headers, its tests pytest, the README's example and the notebooks (python/examples)
# matplotlib, the notebooks' test nbclient and ipykernel (and jupyter-nbconvert for HTML),
# `pip install .` python3-mesonpy and patchelf (which meson-python runs on librelcol). RELCOL_PYTHON=disabled
# leaves them out and configures without it (default auto: built when they are there).
RELCOL_PYTHON=${RELCOL_PYTHON:-auto}
if [ "$RELCOL_PYTHON" != disabled ]; then
    RELCOL_PACKAGES+=(python3-dev python3-cffi python3-numpy python3-pytest python3-matplotlib
                      python3-nbclient python3-ipykernel jupyter-nbconvert python3-mesonpy patchelf)
fi

# The browser page (web/, issue 20): Debian's emscripten (node-acorn: its optimiser's
# parser; dpkg-dev: apt-get source unpacks cJSON's source for it) and Chromium for the
# page's test. Installed by web/build.sh and web/test.sh, not by every configuration.
RELCOL_WEB_PACKAGES=(emscripten node-acorn dpkg-dev chromium)
# node and node-ws for the page's test (web/cdp.mjs speaks the DevTools protocol to chromium
# over ws): Debian packages, so the test needs no npm registry. web/test.sh installs them
# only when node or ws is missing, so a node from elsewhere is left as it is.
RELCOL_NODE_PACKAGES=(nodejs node-ws)

relcol_install_packages() {
    relcol_install_list "${RELCOL_PACKAGES[@]}"
}

# relcol_install_list PKG... : install those of the Debian packages that are missing
relcol_install_list() {
    local missing=()
    for p in "$@"; do
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
        meson setup "$dir" -Dpython="$RELCOL_PYTHON" "$@"
    fi
    meson compile -C "$dir"
}
