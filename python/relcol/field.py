"""A uniform field (papers/gravity.md) from Python: the scenario key "gravity" checked with
messages naming the wrong value, the profile of a gas along the field computed from its
state in numpy (no loop over balls), and relcol-sim's profiles.csv read back.

    Sim(scenario, gravity={"g": 0.5, "coupling": "equivalence"})    the field on a run
    Sim(..., gravity={"g": 1, "coupling": "newtonian", "axis": 0})  along -x
    sim.profile(slabs=20)                 density and kT per slab (a structured array)
    read_profiles(path)                   relcol-sim's profiles.csv as named columns

The columns are those of relcol-sim's profiles.csv (apps/sim/profiles.c), so a profile from
a Sim and one from relcol-sim compare column by column: z (the slab's centre), n (balls in
the slab), density (n per volume), kT_along = <p_z v_z>, kT_across = <p_perp . v_perp>/(d-1),
kT_sqrt_g00 = (1 + g z/c^2) <p . v>/d (equivalence; <p . v>/d otherwise), each with its
standard error (*_err: Poisson for n, the scatter of the slab's balls for the means)."""
import math
import os
import re

import numpy as np

from ._relcol import ffi, lib
from .errors import ScenarioError


def couplings():
    """The library's couplings of the field (rc_gravity_couplings), by name."""
    out, i = [], 0
    while lib.rc_gravity_couplings[i] != ffi.NULL:
        out.append(ffi.string(lib.rc_gravity_couplings[i].name).decode())
        i += 1
    return out


def _err(name, where, reason):
    return ScenarioError("%s: %s: %s" % (name, where, reason))


def check_gravity(grav, dim, name="Sim"):
    """The "gravity" entry {"g": g > 0, "coupling": name, "axis": optional} checked: returns
    (g, coupling, axis), axis an int in [0, dim) (default the last); a ScenarioError (a
    ValueError) naming the key otherwise."""
    if not isinstance(grav, dict):
        raise _err(name, "gravity", "must be a dict {\"g\": g, \"coupling\": \"newtonian\" or "
                   "\"equivalence\", \"axis\": optional}, not %r" % (grav,))
    unknown = sorted(set(grav) - {"g", "coupling", "axis"})
    if unknown:
        raise _err(name, "gravity.%s" % unknown[0], "unknown key (expected g, coupling, axis)")
    g = grav.get("g")
    if isinstance(g, bool) or not isinstance(g, (int, float, np.integer, np.floating)):
        raise _err(name, "gravity.g", "must be a number > 0 (the acceleration at the floor), "
                   "not %r" % (g,))
    g = float(g)
    if not math.isfinite(g):
        raise _err(name, "gravity.g", "must be finite, not %r" % g)
    if not g > 0:
        raise _err(name, "gravity.g", "must be > 0 (the acceleration at the floor; no field: "
                   "leave gravity out), not %r" % g)
    cp = grav.get("coupling")
    names = couplings()
    if cp not in names:
        raise _err(name, "gravity.coupling", "%s (expected one of: %s)"
                   % ("is required" if cp is None else "unknown coupling %r" % (cp,),
                      ", ".join(names)))
    axis = grav.get("axis", dim - 1 if dim else None)
    if axis is not None:
        if isinstance(axis, bool) or not isinstance(axis, (int, np.integer)):
            raise _err(name, "gravity.axis", "must be an integer axis 0..%d, not %r"
                       % (dim - 1, axis))
        if not 0 <= int(axis) < dim:
            raise _err(name, "gravity.axis", "must be an axis of the %d-D box, 0..%d, not %d"
                       % (dim, dim - 1, axis))
        axis = int(axis)
    return g, cp, axis


def profile(state, height, g=0.0, c=math.inf, coupling=None, axis=-1, slabs=20, box=None):
    """The profile of the balls of state (a dict with x, p, v: (N, dim), as Sim.state() or
    read_snapshot give) along axis (default the last), in `slabs` slabs of [0, height]: a
    structured numpy array of relcol-sim's profiles.csv columns (the module's documentation),
    for one state. box: the box's edges (for the density's slab volume; default 1 across)."""
    x, p, v = (np.asarray(state[k], dtype=float) for k in ("x", "p", "v"))
    if x.ndim != 2 or p.shape != x.shape or v.shape != x.shape:
        raise ValueError("profile: state x, p, v must be (N, dim) arrays of one shape, not %s, "
                         "%s, %s" % (x.shape, p.shape, v.shape))
    n, dim = x.shape
    slabs = int(slabs)
    if slabs < 1:
        raise ValueError("profile: slabs must be >= 1, not %d" % slabs)
    height = float(height)
    if not (height > 0 and math.isfinite(height)):
        raise ValueError("profile: height must be a finite number > 0, not %r" % height)
    ax = axis % dim
    ic2 = 0.0 if math.isinf(c) else 1.0 / (c * c)
    z = x[:, ax]
    k = np.clip((z / height * slabs).astype(np.int64), 0, slabs - 1)
    pv = np.einsum("ij,ij->i", p, v)
    along = p[:, ax] * v[:, ax]
    across = (pv - along) / max(dim - 1, 1)
    lapse = (1.0 + g * z * ic2 if coupling == "equivalence" else 1.0) * pv / dim
    cnt = np.bincount(k, minlength=slabs).astype(float)

    def mean_err(q):
        s1 = np.bincount(k, q, minlength=slabs)
        s2 = np.bincount(k, q * q, minlength=slabs)
        with np.errstate(invalid="ignore", divide="ignore"):
            m = np.where(cnt > 0, s1 / cnt, np.nan)
            e = np.where(cnt > 1, np.sqrt(np.maximum(s2 / cnt - m * m, 0) / (cnt - 1)), np.nan)
        return m, e

    vol = height / slabs
    if box is not None:
        vol *= float(np.prod([b for i, b in enumerate(box) if i != ax]))
    out = np.zeros(slabs, dtype=PROFILE_DTYPE)
    out["z"] = height * (np.arange(slabs) + 0.5) / slabs
    out["n"], out["n_err"] = cnt, np.sqrt(cnt)
    out["density"], out["density_err"] = cnt / vol, np.sqrt(cnt) / vol
    for name, q in (("kT_along", along), ("kT_across", across), ("kT_sqrt_g00", lapse)):
        out[name], out[name + "_err"] = mean_err(q)
    return out


PROFILE_COLUMNS = ("z", "n", "n_err", "density", "density_err", "kT_along", "kT_along_err",
                   "kT_across", "kT_across_err", "kT_sqrt_g00", "kT_sqrt_g00_err")
PROFILE_DTYPE = np.dtype([(c, "f8") for c in PROFILE_COLUMNS])

_HEAD = re.compile(r"coupling (\w+), g ([^,]+), c ([^)]+)\), (\d+) states")


def read_profiles(path):
    """relcol-sim's profiles.csv (a run with "gravity"; path the file or its folder) as a
    dict: "table", a structured numpy array with the file's named columns (z, n, n_err,
    density, density_err, kT_along, ..., kT_sqrt_g00_err), each column also as its own
    array under its name; and the run's coupling, g, c (math.inf classically) and samples
    (states gathered) from the file's first line. ValueError naming the file if it is not
    one."""
    path = os.fspath(path)
    if os.path.isdir(path):
        path = os.path.join(path, "profiles.csv")
    with open(path, encoding="utf-8") as f:
        first = f.readline()
        header = f.readline().strip().split(",")
    m = _HEAD.search(first)
    if not first.startswith("#") or not m or tuple(header) != PROFILE_COLUMNS:
        raise ValueError("%s: not a relcol-sim profiles.csv (first line %r, header %r)"
                         % (path, first.strip()[:80], header))
    data = np.loadtxt(path, delimiter=",", comments="#", skiprows=2, ndmin=2)
    if data.shape[1] != len(PROFILE_COLUMNS):
        raise ValueError("%s: rows of %d values, the header names %d"
                         % (path, data.shape[1], len(PROFILE_COLUMNS)))
    table = np.zeros(len(data), dtype=PROFILE_DTYPE)
    for i, c in enumerate(PROFILE_COLUMNS):
        table[c] = data[:, i]
    c = float(m.group(3))
    out = {"table": table, "coupling": m.group(1), "g": float(m.group(2)),
           "c": c, "samples": int(m.group(4))}
    out.update({name: table[name] for name in PROFILE_COLUMNS})
    return out
