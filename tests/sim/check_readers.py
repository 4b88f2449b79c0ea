#!/usr/bin/env python3
"""check_readers.py RELCOL_SIM TMPDIR -- relcol-sim's files as the tools people use read
them: the H5MD trajectory with h5py (structure against the H5MD 1.1 specification, values
against the CSV snapshots at the same times), the extended XYZ with ASE (positions,
velocities, masses, momenta), the snapshots with csv.DictReader and numpy.genfromtxt.
Exit 0 all passed, 1 a check failed, 77 a reader is not installed (meson: skipped)."""
import csv
import json
import math
import os
import re
import subprocess
import sys

try:
    import numpy as np
    import h5py
    import ase.io
except ImportError as e:  # (the tests' packages: scripts/setup.sh installs them)
    print(f"skip: {e}")
    sys.exit(77)

sim, tmp = sys.argv[1], sys.argv[2]
failures = 0


def check(cond, what):
    global failures
    print(("ok   " if cond else "FAIL ") + what)
    if not cond:
        failures += 1
    return cond


def run(name, scenario):
    out = os.path.join(tmp, name)
    path = os.path.join(tmp, name + ".json")
    with open(path, "w") as f:
        json.dump(scenario, f)
    r = subprocess.run([sim, path, "--out", out], capture_output=True, text=True)
    check(r.returncode == 0, f"{name}: relcol-sim ran ({r.stdout.strip()} {r.stderr.strip()})")
    return out


def snapshots(out):
    """{t: {column: numpy array}} from the CSV snapshots, read by csv.DictReader."""
    snaps = {}
    d = os.path.join(out, "snapshots")
    for fn in sorted(os.listdir(d)):
        with open(os.path.join(d, fn), newline="") as f:
            rows = list(csv.DictReader(f))
        cols = {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}
        snaps[cols["t"][0]] = cols
    return snaps


def vec(cols, prefix, dim):
    return np.stack([cols[prefix + a] for a in "xyz"[:dim]], axis=1)


def check_h5md(name, out, sc, n):
    dim, c = sc["dim"], sc["c"]
    c = math.inf if c == "inf" else c
    dt, t0, t1 = sc["outputs"]["h5md_every"], sc.get("time", 0.0), sc["t_end"]
    f = h5py.File(os.path.join(out, "trajectory.h5"), "r")
    # /h5md: version [1, 1] (Integer[2]), author and creator groups with name attributes
    h = f["h5md"]
    check(list(h.attrs["version"]) == [1, 1] and h.attrs["version"].dtype.kind == "i",
          f"{name}: /h5md version [1, 1]")
    check(isinstance(h["author"].attrs["name"], bytes) and len(h["author"].attrs["name"]) > 0,
          f"{name}: /h5md/author name")
    check(h["creator"].attrs["name"] == b"relcol-sim" and "version" in h["creator"].attrs,
          f"{name}: /h5md/creator name and version")
    # /particles/all/box: dimension, boundary (periodic or none per axis), edges
    box = f["particles/all/box"]
    bnd = sc.get("boundary", "walls")
    bnd = [bnd] * dim if isinstance(bnd, str) else bnd
    want = [b"periodic" if b == "periodic" else b"none" for b in bnd]
    check(int(box.attrs["dimension"]) == dim, f"{name}: box dimension {dim}")
    check([bytes(b) for b in box.attrs["boundary"]] == want, f"{name}: box boundary {want}")
    # time-dependent elements: step (integer), time (float), value [frames][N](D),
    # extensible along time and chunked
    frames = int(math.floor((t1 - t0) / dt + 1e-9)) + 1
    # the box's edges: a time series (the form MDAnalysis reads), the same box every frame
    ev = box["edges/value"][:]
    L = np.diag(ev[0]) if ev.ndim == 3 else np.zeros(1)
    check(ev.shape == (frames, dim, dim) and np.all(ev == ev[0]) and np.all(L > 0) and
          np.array_equal(ev[0], np.diag(L)) and
          box["edges/step"] == f["particles/all/position/step"] and
          box["edges/time"] == f["particles/all/position/time"],
          f"{name}: box edges value[{frames}][{dim}][{dim}], constant, diagonal, position's"
          " step and time")
    # units (H5MD's units module strings) on every dimensionful dataset; none on image
    units = {"position/value": "nm", "velocity/value": "nm ps-1", "mass/value": "u",
             "rest_mass/value": "u", "momentum/value": "u nm ps-1", "proper_time/value": "ps",
             "position/time": "ps", "box/edges/value": "nm", "radius": "nm"}
    got = {k: f["particles/all"][k].attrs.get("unit") for k in units}
    check(all(got[k] == units[k] for k in units) and
          ("image" not in f["particles/all"] or
           "unit" not in f["particles/all/image/value"].attrs),
          f"{name}: unit attributes {got}")
    shapes = {"position": (n, dim), "velocity": (n, dim), "mass": (n,), "rest_mass": (n,),
              "momentum": (n, dim), "proper_time": (n,)}
    if "periodic" in bnd:
        shapes["image"] = (n, dim)
    all_ = f["particles/all"]
    for el, shape in shapes.items():
        g = all_[el]
        ok = (g["step"].dtype.kind == "i" and g["time"].dtype.kind == "f" and
              g["value"].shape == (frames,) + shape and g["value"].maxshape[0] is None and
              g["value"].chunks is not None and g["step"].shape == (frames,) and
              g["time"].shape == (frames,))
        check(ok, f"{name}: {el}: step, time, value{(frames,) + shape}, extensible, chunked")
    t = all_["position/time"][:]
    step = all_["position/step"][:]
    check(np.array_equal(t, t0 + dt * step) and step[0] == 0 and np.all(np.diff(step) == 1),
          f"{name}: time = from + step * h5md_every, steps 0..{frames - 1}")
    check(all_["species"].shape == (n,) and all_["species"].dtype.kind == "i",
          f"{name}: species Integer[N]")
    check(all_["radius"].shape == (n,), f"{name}: radius [N]")
    pc = f["parameters"].attrs["c"]
    check(pc == c, f"{name}: parameters c = {pc} (scenario {c})")
    scen = json.loads(f["parameters/scenario"][()].decode())
    check(scen["dim"] == dim and len(scen["balls"]) == n, f"{name}: parameters/scenario is the run's")
    # values: every snapshot time is a frame, and its numbers are the CSV's, to the bit
    snaps = snapshots(out)
    for ts, cols in snaps.items():
        k = np.nonzero(t == ts)[0]
        if not check(len(k) == 1, f"{name}: t = {ts}: a frame at the snapshot's time"):
            continue
        k = k[0]
        same = (np.array_equal(all_["position/value"][k], vec(cols, "", dim)) and
                np.array_equal(all_["momentum/value"][k], vec(cols, "p", dim)) and
                np.array_equal(all_["velocity/value"][k], vec(cols, "v", dim)) and
                np.array_equal(all_["rest_mass/value"][k], cols["m"]) and
                np.array_equal(all_["proper_time/value"][k], cols["tau"]) and
                np.array_equal(all_["mass/value"][k], cols["m"] * cols["gamma"]) and
                np.array_equal(all_["radius"][:], cols["r"]))
        if "image" in shapes:
            same = same and np.array_equal(all_["image/value"][k], vec(cols, "image_", dim))
        check(same, f"{name}: t = {ts}: position, velocity, momentum, masses, proper time"
                    " equal the snapshot's to the bit")
    f.close()
    return snaps


def check_ase(name, out, snaps, dim):
    frames = ase.io.read(os.path.join(out, "trajectory.xyz"), index=":")
    times = [a.info["Time"] for a in frames]
    for ts, cols in snaps.items():
        if ts not in times:
            check(False, f"{name}: ASE: a frame at t = {ts}")
            continue
        a = frames[times.index(ts)]
        v, p, x = vec(cols, "v", dim), vec(cols, "p", dim), vec(cols, "", dim)
        # species X: ASE's dummy (atomic number 0), not an element such as boron
        check(set(a.get_chemical_symbols()) == {"X"} and not a.get_atomic_numbers().any(),
              f"{name}: ASE at t = {ts}: species X (atomic number 0), no element")
        # %.17g round-trips: the columns ASE stores are the snapshot's doubles to the bit
        same = (np.array_equal(a.get_positions()[:, :dim], x) and
                np.array_equal(a.arrays["velo"][:, :dim], v) and
                np.array_equal(a.get_momenta()[:, :dim], p) and
                np.array_equal(a.get_masses(), cols["m"] * cols["gamma"]) and
                np.array_equal(a.arrays["rest_mass"], cols["m"]) and
                np.array_equal(a.arrays["radius"], cols["r"]))
        check(same and np.abs(v).max() > 0, f"{name}: ASE at t = {ts}: positions, velo, "
              "get_momenta(), get_masses() (= gamma m), rest_mass, radius equal the snapshot's"
              " to the bit")
        # get_velocities() is ASE's p / M: v to round-off (a division of two doubles)
        check(np.allclose(a.get_velocities()[:, :dim], v, rtol=4e-16, atol=4e-16),
              f"{name}: ASE at t = {ts}: get_velocities() = v to round-off")


def check_csv_readers(name, out, n, dim):
    d = os.path.join(out, "snapshots")
    fn = os.path.join(d, sorted(os.listdir(d))[0])
    with open(fn, newline="") as f:
        r = csv.DictReader(f)
        rows = list(r)
    want = ["ball", "t"] + list("xyz"[:dim])
    check(r.fieldnames[:2 + dim] == want and len(rows) == n and float(rows[0]["x"]) >= 0,
          f"{name}: csv.DictReader: columns {r.fieldnames[:4]}..., {len(rows)} rows")
    g = np.genfromtxt(fn, delimiter=",", names=True)
    check(g.dtype.names[:2 + dim] == tuple(want) and g.shape == (n,) and
          np.array_equal(g["ball"], np.arange(n)) and not np.isnan(g["tau"]).any(),
          f"{name}: numpy.genfromtxt(names=True): {len(g.dtype.names)} columns, {g.shape[0]} rows")


cases = {
    # 3-D, relativistic and inelastic (rest masses grow, gamma > 1), periodic on two axes
    "rel3d": {"relcol": 1, "dim": 3, "boundary": ["periodic", "walls", "periodic"], "c": 1,
              "restitution": {"ball": 0.8, "wall": 1}, "contact_frame": "zmf", "t_end": 6,
              "generate": {"kind": "gas", "n": 50, "radius": 1, "packing": 0.2, "v_rms": 0.6},
              "outputs": {"snapshots": [0, 2.5, 6], "h5md_every": 0.5, "xyz_every": 0.5,
                          "plots": False, "gif": False}},
    # 2-D classical (c = inf) with walls
    "cls2d": {"relcol": 1, "dim": 2, "c": "inf", "t_end": 4,
              "generate": {"kind": "gas", "n": 40, "radius": 1, "packing": 0.2, "v_rms": 1},
              "outputs": {"snapshots": {"every": 2}, "h5md_every": 0.25, "xyz_every": 1,
                          "plots": False, "gif": False}},
}
for name, sc in cases.items():
    out = run(name, sc)
    n = sc["generate"]["n"]
    snaps = check_h5md(name, out, sc, n)
    check_ase(name, out, snaps, sc["dim"])
    check_csv_readers(name, out, n, sc["dim"])
    # (.NAME.relcol-PID.XXXXXX; .relcol-run and its folder are the published run)
    left = [x for x in os.listdir(out) if re.search(r"\.relcol-[0-9]", x)]
    check(not left, f"{name}: no temporary files left ({left})")

print(f"{failures} failed" if failures else "all passed")
sys.exit(1 if failures else 0)
