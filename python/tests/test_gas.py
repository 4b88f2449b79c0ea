"""relcol.gas_init and relcol.Gas1D."""
import numpy as np
import pytest

import relcol


def test_gas_init_rms_and_zero_momentum():
    box, b = relcol.gas_init(3, 64, 1.0, 0.2, 0.4, c=1.0, seed=7)
    v = relcol.velocity(b["m"], b["p"], 1.0)
    assert np.sqrt(np.mean(np.sum(v * v, axis=1))) == pytest.approx(0.4, rel=1e-12)
    assert np.abs(b["p"].sum(axis=0)).max() < 1e-13 * np.abs(b["p"]).sum()
    assert len(box) == 3 and box[0] == box[1] == box[2]


def test_gas1d_conserves_energy():
    n = 50
    rng = np.random.default_rng(1)
    x = np.sort(rng.uniform(0, 1, n))
    m = rng.uniform(0.5, 2, n)
    p = rng.normal(size=n)
    g = relcol.Gas1D(x, m, p, length=1.0, c=1.0)
    e0 = relcol.mass_rel(m, p[:, None], 1.0).sum()
    g.advance(50.0)
    x1, m1, p1 = g.state()
    assert g.time == 50.0 and np.all(np.diff(x1) >= 0)
    assert relcol.mass_rel(m1, p1[:, None], 1.0).sum() == pytest.approx(e0, rel=1e-12)
    assert g.stats()["pair_events"] > 1000
    with pytest.raises(relcol.RelcolError) as e:
        relcol.Gas1D([0.5, 0.2], 1, [0, 0])
    assert e.value.index == 1


def test_gas1d_worldlines_from_events():
    """step() and segment() rebuild every worldline: the segment an event ends reaches
    the event's point, and the state at a later time lies on the current segments."""
    n = 40
    rng = np.random.default_rng(3)
    x = np.sort(rng.uniform(0, 40, n))
    g = relcol.Gas1D(x, rng.choice([1.0, 2.0], n), rng.normal(size=n), length=40.0, c=1.0)
    seg = [g.segment(i) for i in range(n)]
    assert seg[0]["t"] == 0.0 and seg[0]["x"] == x[0]
    events = 0
    while (ev := g.step(30.0)) is not None:
        events += 1
        last = ev["i"] + 1 if ev["kind"] == "pair" else ev["i"]
        for i in range(ev["i"], last + 1):
            s = seg[i]
            assert s["x"] + s["v"] * (ev["t"] - s["t"]) == pytest.approx(ev["x"], abs=1e-10)
            seg[i] = g.segment(i)
            assert seg[i]["t"] == ev["t"] and seg[i]["x"] == ev["x"]
    assert events > 100 and g.time == 30.0
    xs = g.state()[0]
    on = [min(max(s["x"] + s["v"] * (30.0 - s["t"]), 0.0), 40.0) for s in seg]
    assert np.array_equal(xs, on)
    with pytest.raises(relcol.RelcolError):
        g.segment(n)
