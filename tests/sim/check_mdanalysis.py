#!/usr/bin/env python3
"""check_mdanalysis.py RELCOL_SIM -- relcol-sim's trajectory.h5 read by MDAnalysis'
H5MDReader (Debian's python3-mdanalysis 2.4) and by h5py, the two against each other: time,
positions, velocities and the box of every frame, and the masses (which MDAnalysis' reader
does not read from any H5MD file: h5py's, tied to MDAnalysis' velocities by p = M v).
MDAnalysis holds float32 in its own units (Angstrom, ps): the expected values are h5py's
doubles rounded to float32 and scaled by 10 (nm -> Angstrom) in float32, as its reader does.
Every outputs.h5md choice below that keeps positions (float32 included: its values the
float64 run's rounded to nearest) is read so; the key's bad values are refused by path.
Exit 0 all passed, 1 a check failed, 77 MDAnalysis or h5py is not installed (skipped)."""
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import warnings

try:
    import numpy as np
    import h5py
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # (a DeprecationWarning of its TPR parser)
        import MDAnalysis as mda
except ImportError as e:
    print(f"skip: {e}")
    sys.exit(77)

sim = sys.argv[1]
tmp = tempfile.mkdtemp(prefix="check-mdanalysis.")
failures = 0


def check(cond, what):
    global failures
    print(("ok   " if cond else "FAIL ") + what)
    if not cond:
        failures += 1


# What outputs.h5md chooses: the default (every element, float64) and choices that keep
# the positions (MDAnalysis' reader needs them), float32 among them; None: the key absent.
CHOICES = [None,
           {"fields": ["position"], "precision": "float32", "scenario": False},
           {"fields": ["position", "velocity"], "precision": "float32"},
           {"fields": ["velocity", "position", "mass", "momentum"], "precision": "float64"},
           {"fields": ["position", "mass", "momentum", "rest_mass"], "precision": "float32"}]

# 3-D (MDAnalysis reads only 3-D boxes), relativistic, inelastic (M = gamma m changes at
# every collision), periodic on two axes
n = 60
for choice in CHOICES:
    name = json.dumps(choice) if choice else "default"
    out = os.path.join(tmp, "out")
    sc = {"relcol": 1, "dim": 3, "boundary": ["periodic", "walls", "periodic"], "c": 1,
          "restitution": {"ball": 0.8, "wall": 1}, "t_end": 3,
          "generate": {"kind": "gas", "n": n, "radius": 1, "packing": 0.2, "v_rms": 0.6},
          "outputs": {"dir": out, "h5md_every": 0.25, "plots": False,
                      "gif": False, "summary": False}}
    if choice:
        sc["outputs"]["h5md"] = choice
    fields = set(choice["fields"]) if choice and "fields" in choice else \
        {"position", "velocity", "mass", "momentum", "rest_mass", "proper_time", "image"}
    single = bool(choice) and choice.get("precision") == "float32"
    path = os.path.join(tmp, "scenario.json")
    with open(path, "w") as fh:
        json.dump(sc, fh)
    r = subprocess.run([sim, path], capture_output=True, text=True)
    check(r.returncode == 0, f"{name}: relcol-sim ran ({r.stderr.strip()[:200]})")
    h5 = os.path.join(out, "trajectory.h5")

    f = h5py.File(h5, "r")
    a = f["particles/all"]
    have = {k for k in a if k not in ("box", "species", "radius")}
    check(have == fields, f"{name}: the elements written are the ones chosen ({sorted(have)})")
    want = np.float32 if single else np.float64
    check(all(a[k + "/value"].dtype == want for k in fields if k != "image"),
          f"{name}: values stored as {want.__name__}")
    check(("scenario" in f["parameters"]) == (not choice or choice.get("scenario", True)),
          f"{name}: parameters/scenario written as chosen")
    u = mda.Universe.empty(n, trajectory=False)
    u.load_new(h5, format="H5MD")  # convert_units=True: it demands readable units
    traj = u.trajectory
    check(traj.units == {"time": "ps", "length": "nm",
                         "velocity": "nm/ps" if "velocity" in fields else None, "force": None},
          f"{name}: MDAnalysis read the units {traj.units}")
    frames = a["position/value"].shape[0]
    check(traj.n_frames == frames == 13, f"{name}: MDAnalysis: {traj.n_frames} frames, "
          f"h5py: {frames}")

    f32, ten = np.float32, np.float32(10)
    moved = False
    for ts in traj:
        k = ts.frame
        x = a["position/value"][k]
        L = np.diag(a["box/edges/value"][k])
        check(ts.time == a["position/time"][k], f"{name} frame {k}: time {ts.time} = h5py's")
        check(np.array_equal(ts.positions, x.astype(f32) * ten),
              f"{name} frame {k}: positions = h5py's, as float32 in Angstrom")
        if "velocity" in fields:
            v = a["velocity/value"][k]
            check(np.array_equal(ts.velocities, v.astype(f32) * ten),
                  f"{name} frame {k}: velocities = h5py's, as float32 in Angstrom/ps")
        else:
            check(not ts.has_velocities, f"{name} frame {k}: no velocities (none written)")
        check(np.array_equal(ts.dimensions, np.concatenate([L.astype(f32) * ten, [90, 90, 90]])
                             .astype(f32)), f"{name} frame {k}: box {ts.dimensions} = h5py's edges")
        if {"velocity", "mass", "momentum"} <= fields:
            # masses: h5py's, the M of p = M v with MDAnalysis' velocity (float32: relative
            # 2^-22; stored as float32, m, p and v each carry 2^-24 more)
            m, p = a["mass/value"][k].astype(float), a["momentum/value"][k].astype(float)
            pv = m[:, None] * ts.velocities.astype(float) / 10
            check(np.allclose(pv, p, rtol=2.0 ** -21, atol=2.0 ** -21 * np.abs(p).max()),
                  f"{name} frame {k}: h5py's masses M: M * MDAnalysis' v = h5py's momentum")
        if {"mass", "rest_mass"} <= fields:
            check(np.all(a["mass/value"][k] >= a["rest_mass/value"][k]),
                  f"{name} frame {k}: M >= m")
        moved |= k > 0 and not np.array_equal(x, a["position/value"][0])
    check(moved, f"{name}: the balls moved (the frames differ)")
    if single:
        # float32 as stated: each value the engine's double rounded to nearest, relative
        # 2^-24; the float64 run of the same scenario (same bits: writing changes nothing)
        sc["outputs"]["h5md"] = dict(choice, precision="float64")
        sc["outputs"]["dir"] = out + "64"
        with open(path, "w") as fh:
            json.dump(sc, fh)
        subprocess.run([sim, path], capture_output=True, check=True)
        with h5py.File(os.path.join(out + "64", "trajectory.h5"), "r") as g:
            b = g["particles/all"]
            check(all(np.array_equal(a[k + "/value"][()], b[k + "/value"][()].astype(np.float32))
                      for k in fields if k != "image"),
                  f"{name}: float32 values = the float64 run's rounded to nearest")
            x64, x32 = b["position/value"][()], a["position/value"][()].astype(float)
            rel = np.max(np.abs(x32 - x64) / np.maximum(np.abs(x64), 1e-300))
            check(rel <= 2.0 ** -24, f"{name}: float32 positions within 2^-24 relative "
                  f"(largest {rel:.3g})")
    f.close()
# outputs.h5md refused with its path and reason (exit 2), and carried by --dump (so a
# continued run writes what the first wrote)
base = {"relcol": 1, "dim": 3, "c": 1, "t_end": 1, "box": [10, 10, 10],
        "balls": [{"x": [5, 5, 5], "r": 1}], "outputs": {"dir": os.path.join(tmp, "bad"),
                                                          "h5md_every": 0.5}}
for h5, why in [({"fields": ["position", "colour"]}, "outputs.h5md.fields[1]: unknown field 'colour'"),
                ({"fields": ["position", "position"]}, "outputs.h5md.fields[1]: 'position' given twice"),
                ({"fields": ["image"]}, "outputs.h5md.fields[0]: image (the periodic wraps) needs a periodic axis"),
                ({"fields": []}, "outputs.h5md.fields: must be a non-empty list"),
                ({"precision": "float16"}, "outputs.h5md.precision: unknown precision 'float16'"),
                ({"scenario": 1}, "outputs.h5md.scenario: must be true or false"),
                ({"every": 1}, "outputs.h5md.every: unknown key"),
                ([], "outputs.h5md: must be an object"),
                (None, "outputs.h5md: says what trajectory.h5 holds, but outputs.h5md_every is not > 0")]:
    sc = json.loads(json.dumps(base))
    sc["outputs"]["h5md"] = h5 if h5 is not None else {"fields": ["position"]}
    if h5 is None:
        del sc["outputs"]["h5md_every"]
    with open(path, "w") as fh:
        json.dump(sc, fh)
    r = subprocess.run([sim, path], capture_output=True, text=True)
    check(r.returncode == 2 and why in r.stderr, f"refused: {why} (exit {r.returncode}: "
          f"{r.stderr.strip()[:160]})")
sc = json.loads(json.dumps(base))
sc["outputs"]["h5md"] = {"fields": ["velocity", "position"], "precision": "float32",
                         "scenario": False}
with open(path, "w") as fh:
    json.dump(sc, fh)
r = subprocess.run([sim, "--dump", path], capture_output=True, text=True)
dumped = json.loads(r.stdout)["outputs"].get("h5md") if r.returncode == 0 else None
check(dumped == {"fields": ["position", "velocity"], "precision": "float32", "scenario": False},
      f"--dump carries outputs.h5md ({dumped})")

# (.NAME.relcol-PID.XXXXXX; .relcol-run and its folder are the published run)
left = [x for x in os.listdir(os.path.join(tmp, "out")) if re.search(r"\.relcol-[0-9]", x)]
check(not left, f"no temporary files left ({left})")
shutil.rmtree(tmp)
print(f"{failures} failed" if failures else "all passed")
sys.exit(1 if failures else 0)
