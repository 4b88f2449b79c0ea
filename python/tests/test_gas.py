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
