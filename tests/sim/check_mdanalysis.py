#!/usr/bin/env python3
"""check_mdanalysis.py RELCOL_SIM -- relcol-sim's trajectory.h5 read by MDAnalysis'
H5MDReader (Debian's python3-mdanalysis 2.4) and by h5py, the two against each other: time,
positions, velocities and the box of every frame, and the masses (which MDAnalysis' reader
does not read from any H5MD file: h5py's, tied to MDAnalysis' velocities by p = M v).
MDAnalysis holds float32 in its own units (Angstrom, ps): the expected values are h5py's
doubles rounded to float32 and scaled by 10 (nm -> Angstrom) in float32, as its reader does.
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


# 3-D (MDAnalysis reads only 3-D boxes), relativistic, inelastic (M = gamma m changes at
# every collision), periodic on two axes
n = 60
sc = {"relcol": 1, "dim": 3, "boundary": ["periodic", "walls", "periodic"], "c": 1,
      "restitution": {"ball": 0.8, "wall": 1}, "t_end": 3,
      "generate": {"kind": "gas", "n": n, "radius": 1, "packing": 0.2, "v_rms": 0.6},
      "outputs": {"dir": os.path.join(tmp, "out"), "h5md_every": 0.25, "plots": False,
                  "gif": False, "summary": False}}
path = os.path.join(tmp, "scenario.json")
with open(path, "w") as f:
    json.dump(sc, f)
r = subprocess.run([sim, path], capture_output=True, text=True)
check(r.returncode == 0, f"relcol-sim ran ({r.stderr.strip()[:200]})")
h5 = os.path.join(tmp, "out", "trajectory.h5")

f = h5py.File(h5, "r")
a = f["particles/all"]
u = mda.Universe.empty(n, trajectory=False)
u.load_new(h5, format="H5MD")  # convert_units=True: it demands readable units
traj = u.trajectory
check(traj.units == {"time": "ps", "length": "nm", "velocity": "nm/ps", "force": None},
      f"MDAnalysis read the units {traj.units}")
frames = a["position/value"].shape[0]
check(traj.n_frames == frames == 13, f"MDAnalysis: {traj.n_frames} frames, h5py: {frames}")

f32, ten = np.float32, np.float32(10)
moved = False
for ts in traj:
    k = ts.frame
    x, v = a["position/value"][k], a["velocity/value"][k]
    m, p = a["mass/value"][k], a["momentum/value"][k]
    L = np.diag(a["box/edges/value"][k])
    check(ts.time == a["position/time"][k], f"frame {k}: time {ts.time} = h5py's")
    check(np.array_equal(ts.positions, x.astype(f32) * ten) and
          np.array_equal(ts.velocities, v.astype(f32) * ten),
          f"frame {k}: positions and velocities = h5py's, as float32 in Angstrom")
    check(np.array_equal(ts.dimensions, np.concatenate([L.astype(f32) * ten, [90, 90, 90]])
                         .astype(f32)), f"frame {k}: box {ts.dimensions} = h5py's edges")
    # masses: h5py's, the M of p = M v with MDAnalysis' velocity (float32: relative 2^-22)
    pv = m[:, None] * ts.velocities.astype(float) / 10
    check(np.allclose(pv, p, rtol=2.0 ** -21, atol=2.0 ** -21 * np.abs(p).max()) and
          np.all(m >= a["rest_mass/value"][k]),
          f"frame {k}: h5py's masses M >= m, M * MDAnalysis' v = h5py's momentum")
    moved |= k > 0 and not np.array_equal(x, a["position/value"][0])
check(moved, "the balls moved (the frames differ)")
f.close()
# (.NAME.relcol-PID.XXXXXX; .relcol-run and its folder are the published run)
left = [x for x in os.listdir(os.path.join(tmp, "out")) if re.search(r"\.relcol-[0-9]", x)]
check(not left, f"no temporary files left ({left})")
shutil.rmtree(tmp)
print(f"{failures} failed" if failures else "all passed")
sys.exit(1 if failures else 0)
