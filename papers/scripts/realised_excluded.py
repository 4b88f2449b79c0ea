"""The realised excluded region (papers/finite-density.md, section 5.1).

Runs a 2-D periodic gas through relcol.Sim (c = 1, rest radius 1, rest mass 1) and, at
table-time snapshots, counts each ball's neighbours within R = 4 radii. Whatever region
the dynamics keeps a ball's neighbours out of -- the table-frame Minkowski sum, the zmf
contact's own set, pairs caught mid-collision -- the count k_i = n (pi R^2 - V_i) + noise
measures it per ball without a model, and (A)'s first-order law f = J[1 - n(V - <V>)]
then predicts the thermometers' split from the same snapshots:

    theta_pv - theta_gamma = Cov(p.v, k)/2 - Cov(gamma, k)/G'(theta),

G(theta) = <gamma> of the 2-D Jüttner law. If the split measured equals this, the
momentum law is the equilibrium of the excluded region the gas realises; if not, the
collisions share energy in a way no excluded-volume measure describes.

usage: PYTHONPATH=build/python python3 papers/scripts/realised_excluded.py FRAME PACKING
       [N [SNAPSHOTS [SEED]]]      (prints one JSON line; numpy only)"""
import json
import math
import sys

import numpy as np

import relcol

R = 4.0  # the neighbour radius, in rest radii: the pair correlation is 1 beyond it to O(eta^2)


def gamma_mean(theta):
    """<gamma> of the 2-D Jüttner law (apps/gas/juttner.h)."""
    return (1 + 2 * theta + 2 * theta * theta) / (1 + theta)


def theta_of(g):
    lo, hi = 1e-6, 1e3
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if gamma_mean(mid) < g else (lo, mid)
    return 0.5 * (lo + hi)


def counts(x, L):
    """Neighbours within R of each ball, nearest image, in chunks (N^2 distances)."""
    k = np.zeros(len(x))
    for a in range(0, len(x), 512):
        d = x[a:a + 512, None, :] - x[None, :, :]
        d -= L * np.round(d / L)
        k[a:a + 512] = ((d * d).sum(-1) < R * R).sum(1) - 1
    return k


def main(argv):
    if len(argv) < 3:
        sys.exit(__doc__)
    frame, eta = argv[1], float(argv[2])
    n_balls = int(argv[3]) if len(argv) > 3 else 4000
    nsnap = int(argv[4]) if len(argv) > 4 else 400
    seed = int(argv[5]) if len(argv) > 5 else 5
    if not (0 < eta < 0.5) or n_balls < 100 or nsnap < 20:
        sys.exit("realised_excluded.py: PACKING in (0, 0.5), N >= 100, SNAPSHOTS >= 20")
    sim = relcol.Sim({"dim": 2, "c": 1.0, "contact_frame": frame, "boundary": "periodic",
                      "seed": seed, "generate": {"kind": "gas", "n": n_balls, "radius": 1.0,
                                                 "packing": eta, "v_rms": 0.8}})
    L = sim.box
    n = n_balls / np.prod(L)
    tfree = 1.0 / (n * 4.0 * 0.8)  # about a mean free time (cross-section 4 r)
    t = 40 * tfree
    sim.advance(t)
    g, pv, k = [], [], []
    for _ in range(nsnap):
        t += 2 * tfree
        sim.advance(t)
        # each ball's latest segment (in the covariant frame every change at its contact
        # event's table time), the read-out finite-density.md's numbers were made with;
        # state() would read balls whose kink lies ahead on their incoming line
        # (covariant-frame.md section 1)
        st = sim.state(latest=True)
        p = st["p"]
        E = np.sqrt(1.0 + (p * p).sum(1))
        g.append(E)
        pv.append((p * p).sum(1) / E)
        k.append(counts(np.mod(st["x"], L), L))
    g, pv, k = (np.concatenate(a) for a in (g, pv, k))
    nb, per = 10, nsnap // 10 * n_balls  # blocks of snapshots for the errors
    rows = []
    for b in range(nb):
        sl = slice(b * per, (b + 1) * per)
        th = theta_of(g[sl].mean())
        dG = (gamma_mean(th * 1.0001) - gamma_mean(th * 0.9999)) / (0.0002 * th)
        pred = np.cov(pv[sl], k[sl])[0, 1] / 2 - np.cov(g[sl], k[sl])[0, 1] / dG
        rows.append((th, pv[sl].mean() / 2 - th, pred))
    mu, se = np.mean(rows, 0), np.std(rows, 0, ddof=1) / math.sqrt(nb)
    d = sim.diagnostics()
    print(json.dumps({"frame": frame, "packing": eta, "n": n_balls, "snapshots": nsnap,
                      "theta_gamma": mu[0], "split_measured": [mu[1], se[1]],
                      "split_from_counts": [mu[2], se[2]], "overlaps": d["overlaps"],
                      "collisions": d["collisions"]}))


if __name__ == "__main__":
    main(sys.argv)
