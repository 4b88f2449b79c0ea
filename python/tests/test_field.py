"""relcol.Sim in a uniform field (papers/gravity.md): the field given at construction or by
the scenario, bad entries refused naming the key, the field's energy conserved, the field
along another axis, Sim.profile against relcol-sim's own profiles.csv (read_profiles), and
a small colliding gas relaxed from a uniform start to each coupling's equilibrium: the
barometric law with uniform kT (newtonian, c = inf) and Tolman-Ehrenfest (equivalence,
c = 1), by chi^2 p-values. The theory here is written out from papers/gravity.md section 5
(closed forms), not taken from the package."""
import math
import os
import subprocess

import numpy as np
import pytest

import relcol

# the field's equilibrium checks: 300 discs of radius R in the unit box (2-D, periodic
# across, floor and ceiling), relaxed for T_RELAX from a uniform start, then SNAPS states
# DT apart, each a profile of SLABS slabs
N, R, SLABS, T_RELAX, SNAPS, DT = 300, 0.0025, 10, 20.0, 30, 1.0


def gas(**kw):
    s = {"relcol": 1, "dim": 2, "c": "inf", "boundary": ["periodic", "walls"], "seed": 5,
         "generate": {"kind": "gas", "n": N, "radius": R, "packing": N * math.pi * R * R,
                      "v_rms": 0.6}}
    s.update(kw)
    return s


FIELD = {"g": 1.0, "coupling": "newtonian"}


@pytest.mark.parametrize("grav, path, reason", [
    ({"g": -1, "coupling": "newtonian"}, "gravity.g", "> 0"),
    ({"g": 0, "coupling": "newtonian"}, "gravity.g", "> 0"),
    ({"g": math.nan, "coupling": "newtonian"}, "gravity.g", "finite"),
    ({"g": math.inf, "coupling": "newtonian"}, "gravity.g", "finite"),
    ({"g": "1", "coupling": "newtonian"}, "gravity.g", "number"),
    ({"g": 1, "coupling": "rindler"}, "gravity.coupling", "unknown coupling 'rindler'"),
    ({"g": 1}, "gravity.coupling", "required"),
    ({"g": 1, "coupling": "newtonian", "axis": 2}, "gravity.axis", "0..1"),
    ({"g": 1, "coupling": "newtonian", "axis": 0.5}, "gravity.axis", "integer"),
    ({"g": 1, "coupling": "newtonian", "axis": 0}, "gravity.axis", "periodic"),
    ({"g": 1, "coupling": "newtonian", "up": 1}, "gravity.up", "unknown key"),
    ("down", "gravity", "must be a dict"),
])
def test_bad_field_refused(grav, path, reason):
    with pytest.raises(ValueError) as e:
        relcol.Sim(gas(), gravity=grav)
    assert e.value.path == path and reason in e.value.reason, str(e.value)


def test_field_refuses_contracted_frame_and_periodic_floor():
    with pytest.raises(ValueError, match="contact_frame: frame 'table' is not defined in a field"):
        relcol.Sim(gas(contact_frame="table"), gravity=FIELD)
    with pytest.raises(ValueError, match="gravity: the field's axis"):
        relcol.Sim(gas(boundary=["walls", "periodic"]), gravity=FIELD)


@pytest.mark.parametrize("coupling, c", [("newtonian", math.inf), ("newtonian", 2.0),
                                         ("equivalence", 2.0)])
def test_field_energy_conserved(coupling, c):
    # the scenario's own key and the keyword are one field
    a = relcol.Sim(gas(c=c, gravity={"g": 1.0, "coupling": coupling}))
    b = relcol.Sim(gas(c=c), gravity={"g": 1.0, "coupling": coupling})
    assert a.gravity == b.gravity == {"g": 1.0, "coupling": coupling, "axis": 1}
    a.advance(5.0)
    b.advance(5.0)
    assert a.hash() == b.hash()
    d = a.diagnostics()
    # H - booked is conserved by every contact to round-off (papers/gravity.md section 4):
    # 1e-10 relative over some 5000 collisions
    assert d["collisions"] > 2000 and abs(d["field_energy_error"]) < 1e-10, d
    assert relcol.Sim(gas()).gravity is None and "field_energy_error" not in relcol.Sim(gas()).diagnostics()


def test_field_along_another_axis():
    s = relcol.Sim(gas(boundary=["walls", "periodic"]),
                   gravity={"g": 1.0, "coupling": "newtonian", "axis": 0})
    assert s.gravity["axis"] == 0
    x0 = s.positions.mean(axis=0)
    s.advance(3.0)
    x1 = s.positions.mean(axis=0)
    # the gas falls along -x (its mean height drops by a good part of the box), not along y
    assert x1[0] < x0[0] - 0.1 and abs(s.diagnostics()["field_energy_error"]) < 1e-10
    prof = s.profile(SLABS)
    assert prof["n"][0] > 2 * prof["n"][-1] and prof["n"].sum() == N
    with pytest.raises(ValueError, match="gravity.axis"):
        s.save("/tmp/never-written.json")


@pytest.mark.skipif("RELCOL_SIM" not in os.environ, reason="relcol-sim not given")
def test_profiles_csv_read_and_equal_to_sim_profile(tmp_path):
    scn = tmp_path / "atm.json"
    import json
    sc = gas(c=2.0, gravity={"g": 0.8, "coupling": "equivalence"}, t_end=3.0,
             outputs={"dir": str(tmp_path / "o"), "snapshots": {"every": 1.0}})
    scn.write_text(json.dumps(sc))
    subprocess.run([os.environ["RELCOL_SIM"], str(scn), "--no-plots"], check=True,
                   capture_output=True)
    run = relcol.read_run(tmp_path / "o")
    p = run["profiles"]
    assert p["coupling"] == "equivalence" and p["g"] == 0.8 and p["c"] == 2.0
    assert p["table"].dtype.names[:3] == ("z", "n", "n_err") and len(p["z"]) == 20
    # relcol-sim gathers the profile at every output time: the start (a Sim of the same
    # scenario has it) and the snapshots
    start = relcol.Sim(sc)
    snaps = [start.state()] + run["snapshots"]
    assert p["samples"] == len(snaps)
    # the same states through relcol.field.profile, summed as relcol-sim sums them
    box = start.box
    mine = [relcol.field.profile(sn, box[1], 0.8, 2.0, "equivalence", 1, 20, box) for sn in snaps]
    n = np.sum([m["n"] for m in mine], axis=0) / len(mine)
    lapse = np.sum([np.nan_to_num(m["kT_sqrt_g00"]) * m["n"] for m in mine], axis=0) / np.sum([m["n"] for m in mine], axis=0)
    # (profiles.csv prints 10 digits)
    assert np.allclose(n, p["n"], rtol=1e-9, atol=0)
    assert np.allclose(lapse, p["kT_sqrt_g00"], rtol=1e-8, equal_nan=True)
    with pytest.raises(ValueError, match="not a relcol-sim profiles.csv"):
        relcol.read_profiles(tmp_path / "o" / "summary.json")


# ---- the equilibria -------------------------------------------------------------------

def relaxed(coupling, c, g):
    """SNAPS profiles of the gas after T_RELAX, and the start's counts per slab."""
    s = relcol.Sim(gas(c=c), gravity={"g": g, "coupling": coupling})
    start = s.profile(SLABS)["n"]
    s.advance(T_RELAX)
    prof = []
    for q in range(SNAPS):
        s.advance(T_RELAX + (q + 1) * DT)
        prof.append(s.profile(SLABS))
    return s, np.array(prof), start


def mean_var(col):
    """a slab's mean over the snapshots and the variance of that mean (their scatter)"""
    return col.mean(axis=0), col.var(axis=0, ddof=1) / len(col)


def chi2_p(chi, dof):
    from scipy.stats import chi2
    return chi2.sf(chi, dof)


def shares(f, H):
    """each slab's share of the centres' range [R, H - R] under the density f (Simpson)"""
    out = []
    for k in range(SLABS):
        lo, hi = max(k * H / SLABS, R), min((k + 1) * H / SLABS, H - R)
        z = np.linspace(lo, hi, 401)
        w = np.ones(401)
        w[1:-1:2], w[2:-1:2] = 4, 2
        out.append((w * f(z)).sum() * (hi - lo) / 1200)
    out = np.array(out)
    return out / out.sum()


def virial(ideal, H, box_x):
    """counts per slab with the second virial correction of hard discs (diameter 2R): the
    local chemical potential gains 2 B2 n kT, B2 = pi (2R)^2 / 2, so n = A f exp(-2 B2 n),
    A keeping the total; solved by fixed-point iteration"""
    B2, vol = math.pi * (2 * R) ** 2 / 2, H / SLABS * box_x
    A = 1.0
    for _ in range(200):
        n = ideal * N / vol
        for _ in range(50):
            n = A * ideal * N / vol * np.exp(-2 * B2 * n)
        A *= N / (n * vol).sum()
    return n * vol


def pooled(mean, var):
    w = 1 / var
    return (w * mean).sum() / w.sum()


def test_barometric_equilibrium():
    g = 1.0
    s, P, start = relaxed("newtonian", math.inf, g)
    H, m = s.box[1], s.rest_masses.mean()
    kt_m, kt_v = mean_var(P["kT_sqrt_g00"])
    kt = pooled(kt_m, kt_v)
    chi_t = ((kt_m - kt) ** 2 / kt_v).sum()
    want = virial(shares(lambda z: np.exp(-m * g * z / kt), H), H, s.box[0])
    n_m, n_v = mean_var(P["n"])
    chi_n = ((n_m - want) ** 2 / n_v).sum()
    chi_0 = ((start - want) ** 2 / want).sum()
    p_n, p_t, p_0 = chi2_p(chi_n, SLABS - 1), chi2_p(chi_t, SLABS - 1), chi2_p(chi_0, SLABS - 1)
    print("newtonian c inf g %g: kT %.4g, n(z) barometric p %.3f (start p %.1e), kT uniform p %.3f"
          % (g, kt, p_n, p_0, p_t))
    assert p_0 < 1e-6  # the start is off equilibrium
    assert p_n > 1e-3 and p_t > 1e-3


def test_tolman_equilibrium():
    g, c = 0.5, 1.0
    s, P, start = relaxed("equivalence", c, g)
    H, m = s.box[1], s.rest_masses.mean()
    z = P["z"][0]
    lap_m, lap_v = mean_var(P["kT_sqrt_g00"])
    kt0 = pooled(lap_m, lap_v)
    chi_l = ((lap_m - kt0) ** 2 / lap_v).sum()
    tolman = kt0 / (1 + g * z / c ** 2)
    chis = {}
    for col in ("kT_along", "kT_across"):
        mu, var = mean_var(P[col])
        chis[col] = ((mu - tolman) ** 2 / var).sum()
    # local Juttner in 2-D: n ~ T (mc^2 + kT) exp(-mc^2/kT) at T(z) = T0/(1 + g z/c^2)
    th0 = kt0 / (m * c * c)

    def dens(zz):
        th = th0 / (1 + g * zz / c ** 2)
        return th * (1 + th) * np.exp(-1 / th + 1 / th0)

    want = virial(shares(dens, H), H, s.box[0])
    n_m, n_v = mean_var(P["n"])
    chi_n = ((n_m - want) ** 2 / n_v).sum()
    # kT itself falls with height: weighted least squares of the two thermometers' mean
    (am, av), (cm, cv) = mean_var(P["kT_along"]), mean_var(P["kT_across"])
    y, w = (am + cm) / 2, 4 / (av + cv)
    Sw, Sz, Szz, Sy, Szy = w.sum(), (w * z).sum(), (w * z * z).sum(), (w * y).sum(), (w * z * y).sum()
    det = Sw * Szz - Sz * Sz
    slope, serr = (Sw * Szy - Sz * Sy) / det, math.sqrt(Sw / det)
    ps = {k: chi2_p(v, SLABS - 1) for k, v in dict(chis, lapse=chi_l, n=chi_n).items()}
    print("equivalence c %g g %g: theta0 %.4f; p %s; d kT/dz %.4g +- %.2g (%.1f sigma)"
          % (c, g, th0, {k: round(v, 3) for k, v in ps.items()}, slope, serr, -slope / serr))
    assert all(p > 1e-3 for p in ps.values()), ps
    assert slope < -5 * serr
