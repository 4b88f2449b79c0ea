#!/bin/sh
# test_sim_readers.sh RELCOL_SIM CHECK_READERS_PY — runs check_readers.py (relcol-sim's
# H5MD, extended XYZ and CSV snapshots read by h5py, ASE, csv and numpy) with the first
# python3 that has those modules (Debian's python3-h5py, python3-ase, python3-numpy live in
# /usr/bin/python3's path; a python3 earlier on PATH may not see them). 77: none has them.
sim="$1"; py_script="$2"
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
for py in python3 /usr/bin/python3; do
    command -v "$py" > /dev/null 2>&1 || continue
    if "$py" -c 'import h5py, ase.io, numpy' > /dev/null 2>&1; then
        "$py" "$py_script" "$sim" "$tmp"
        exit $?
    fi
done
echo "skip: no python3 with h5py, ase and numpy (apt-get install python3-h5py python3-ase)"
exit 77
