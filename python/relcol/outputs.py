"""Readers of relcol-sim's outputs into numpy (apps/sim/SCENARIO.md, "Outputs"):
summary.json, the CSV snapshots, the H5MD trajectory (through h5py) and a whole output
folder. They read the files as written -- numbers in round-trip form, so the arrays hold
the run's own bits -- and name the file and what is missing when a file is not one."""
import glob
import json
import math
import os

import numpy as np


def _inf(obj):
    """JSON's stand-ins back to numbers: "inf" (c = inf) to math.inf, null to NaN."""
    if isinstance(obj, dict):
        return {k: _inf(v) for k, v in obj.items()}
    if isinstance(obj, list):
        return [_inf(v) for v in obj]
    if obj == "inf":
        return math.inf
    return math.nan if obj is None else obj


def read_summary(path):
    """summary.json (a run's results: conservation errors, counts, timings) as a dict;
    "inf" becomes math.inf and null (an undefined ratio) NaN. path: the file or its
    folder."""
    if os.path.isdir(path):
        path = os.path.join(path, "summary.json")
    with open(path, encoding="utf-8") as f:
        return _inf(json.load(f))


def read_snapshot(path):
    """One snapshot CSV (snapshots/snap-NNNN.csv) as a dict of arrays: t (the time, a
    float), ball (N,), x (N, dim), p, v (N, dim), m, r, tau, gamma (N,), image (N, dim)
    on periodic runs."""
    with open(path, encoding="utf-8") as f:
        header = f.readline().strip().split(",")
    data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    if data.shape[1] != len(header) or header[:2] != ["ball", "t"]:
        raise ValueError("%s: not a relcol-sim snapshot (header %r)" % (path, header))
    col = {name: data[:, k] for k, name in enumerate(header)}
    axes = [a for a in "xyz" if a in col]
    out = {"t": float(col["t"][0]) if len(data) else math.nan,
           "ball": col["ball"].astype(np.int64),
           "x": np.stack([col[a] for a in axes], axis=1),
           "p": np.stack([col["p" + a] for a in axes], axis=1),
           "v": np.stack([col["v" + a] for a in axes], axis=1)}
    for k in ("m", "r", "tau", "gamma"):
        out[k] = col[k]
    if "image_x" in col:
        out["image"] = np.stack([col["image_" + a] for a in axes], axis=1).astype(np.int64)
    return out


def read_snapshots(folder):
    """Every snapshot of an output folder (its snapshots/ subfolder), in time order."""
    if os.path.isdir(os.path.join(folder, "snapshots")):
        folder = os.path.join(folder, "snapshots")
    return [read_snapshot(p) for p in sorted(glob.glob(os.path.join(folder, "snap-*.csv")))]


def read_h5md(path):
    """An H5MD file (relcol-sim's trajectory.h5, or any H5MD 1.x file) through h5py, as a
    dict: for each particles group (relcol-sim writes "all") a dict of its elements -- a
    time-dependent element as {"value": (F, ...), "time": (F,), "step": (F,)}, a fixed one
    as its array -- with "box" holding the box's attributes and edges; and "h5md", the
    file's metadata attributes. Needs h5py (Debian python3-h5py)."""
    import h5py

    def element(obj):
        if isinstance(obj, h5py.Dataset):
            return obj[()]
        if "value" in obj:
            out = {"value": obj["value"][()]}
            for k in ("time", "step"):
                if k in obj:
                    out[k] = obj[k][()]
            out.update({"unit": obj["value"].attrs["unit"]} if "unit" in obj["value"].attrs else {})
            return out
        return {k: element(v) for k, v in obj.items()}

    out = {"particles": {}}
    with h5py.File(path, "r") as f:
        if "h5md" not in f:
            raise ValueError("%s: not an H5MD file (no /h5md group)" % path)
        out["h5md"] = {k: v for k, v in f["h5md"].attrs.items()}
        for name, grp in f.get("particles", {}).items():
            g = {}
            for k, v in grp.items():
                g[k] = element(v)
                if k == "box":
                    g[k] = dict(g[k]) if isinstance(g[k], dict) else {"edges": g[k]}
                    g[k].update({a: v.attrs[a] for a in v.attrs})
            out["particles"][name] = g
        if "observables" in f:
            out["observables"] = {k: element(v) for k, v in f["observables"].items()}
    return out


def read_run(folder):
    """A whole relcol-sim output folder as a dict: summary (read_summary), snapshots
    (read_snapshots), final (final.json as a dict: the state it ended in), h5md
    (read_h5md of trajectory.h5, if written), profiles (relcol.field.read_profiles of
    profiles.csv, a run with "gravity")."""
    out = {"summary": read_summary(folder), "snapshots": read_snapshots(folder)}
    fin = os.path.join(folder, "final.json")
    if os.path.exists(fin):
        with open(fin, encoding="utf-8") as f:
            out["final"] = json.load(f)
    h5 = os.path.join(folder, "trajectory.h5")
    if os.path.exists(h5):
        out["h5md"] = read_h5md(h5)
    if os.path.exists(os.path.join(folder, "profiles.csv")):
        from .field import read_profiles
        out["profiles"] = read_profiles(folder)
    return out
