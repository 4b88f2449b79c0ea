#!/usr/bin/env python3
"""share-map.py — the share of collisions the overlap policy decides in the covariant
frame's periodic gas, by packing: one row per dimension and rms speed, one column per
packing (papers/model-regime.md, section 4; issue 16's bound is 0.1 %).

    PYTHONPATH=build-release/python python3 scripts/share-map.py [collisions] [seed]

Each run: relcol.Sim, N = 2000, c = 1, seed 3 unless given, advanced in steps of 10/eta
until it has at least `collisions` (40 000) collisions. Prints "share% (overlaps/collisions)".
"""
import sys

from relcol import Sim

NCOL = int(sys.argv[1]) if len(sys.argv) > 1 else 40000
SEED = int(sys.argv[2]) if len(sys.argv) > 2 else 3
PACKINGS = (0.005, 0.01, 0.02, 0.03, 0.05, 0.1)

print("dim v_rms " + " ".join("%18s" % ("eta %g" % e) for e in PACKINGS))
for dim in (2, 3):
    for v in (0.5, 0.8):
        row = []
        for eta in PACKINGS:
            s = Sim(dim=dim, c=1.0, contact_frame="covariant", boundary="periodic", seed=SEED,
                    generate={"kind": "gas", "n": 2000, "packing": eta, "v_rms": v})
            t = 0.0
            while s.diagnostics()["collisions"] < NCOL:
                t += 10.0 / eta
                s.advance(t)
            d = s.diagnostics()
            row.append("%18s" % ("%.3f%% (%d/%d)" % (100.0 * d["overlaps"] / d["collisions"],
                                                     d["overlaps"], d["collisions"])))
        print("%3d %5.1f " % (dim, v) + " ".join(row), flush=True)
