"""relcol.collide over arrays: the library's bits pair by pair, conservation, the seed
limits, and library errors as exceptions naming the pair."""
import math

import numpy as np
import pytest

import relcol


def random_pairs(n, c, seed=5, dim=3):
    rng = np.random.default_rng(seed)
    vmax = 0.95 * c if math.isfinite(c) else 3.0
    def vel():
        u = rng.normal(size=(n, dim))
        u /= np.linalg.norm(u, axis=1)[:, None]
        return u * (vmax * rng.uniform(size=n))[:, None]
    m0 = np.exp(rng.uniform(np.log(0.1), np.log(10), n))
    m1 = np.exp(rng.uniform(np.log(0.1), np.log(10), n))
    v0, v1 = vel(), vel()
    nrm = rng.normal(size=(n, dim))
    return m0, relcol.momentum(m0, v0, c), m1, relcol.momentum(m1, v1, c), nrm


@pytest.mark.parametrize("law", [l.name for l in relcol.laws()])
@pytest.mark.parametrize("c", [1.0, 7.0, math.inf])
def test_batch_equals_single_calls(law, c):
    m0, p0, m1, p1, n = random_pairs(300, c)
    out = relcol.collide(m0, p0, m1, p1, n, c=c, eps=0.6, law=law)
    for i in range(0, 300, 7):
        one = relcol.collide(m0[i], p0[i], m1[i], p1[i], n[i], c=c, eps=0.6, law=law)
        assert one.collided == out.collided[i]
        assert one.m0 == out.m0[i] and one.m1 == out.m1[i]
        assert np.array_equal(one.p0, out.p0[i]) and np.array_equal(one.p1, out.p1[i])
    # normals of either sense: about half the pairs approach
    assert 0.3 < out.collided.mean() < 0.7
    # pairs that did not collide are untouched
    keep = ~out.collided
    assert np.array_equal(out.p0[keep], p0[keep]) and np.array_equal(out.m0[keep], m0[keep])


@pytest.mark.parametrize("c", [1.0, 3.0, math.inf])
def test_energy_and_momentum_conserved(c):
    m0, p0, m1, p1, n = random_pairs(2000, c, seed=9)
    out = relcol.collide(m0, p0, m1, p1, n, c=c, eps=0.3)
    # total momentum: a sum of a few terms of size |p|, so a few ulps of the larger |p|
    scale = np.linalg.norm(p0, axis=1) + np.linalg.norm(p1, axis=1)
    dp = np.linalg.norm(out.p0 + out.p1 - p0 - p1, axis=1)
    assert np.all(dp <= 1e-14 * scale)
    if math.isfinite(c):
        # total E/c^2 = M0 + M1 is conserved exactly by the law (relative round-off)
        e0 = relcol.mass_rel(m0, p0, c) + relcol.mass_rel(m1, p1, c)
        e1 = relcol.mass_rel(out.m0, out.p0, c) + relcol.mass_rel(out.m1, out.p1, c)
        assert np.all(np.abs(e1 - e0) <= 1e-13 * e0)
        # inelastic: rest masses never fall
        assert np.all(out.m0 >= m0 * (1 - 1e-15)) and np.all(out.m1 >= m1 * (1 - 1e-15))


def test_seed_limits():
    # equal masses, head-on, elastic, classical: the velocities are exchanged exactly
    r = relcol.collide(1.0, [2.0], 1.0, [-0.5], [1.0])
    assert r.collided and r.p0[0] == -0.5 and r.p1[0] == 2.0 and r.m0 == 1.0
    # eps = 0 at c = 1, +-0.6 c: both at rest, kinetic energy become rest mass gamma(0.6) = 1.25
    r = relcol.collide(1.0, relcol.momentum(1, [0.6], 1), 1.0, relcol.momentum(1, [-0.6], 1),
                       [1.0], c=1, eps=0)
    assert abs(r.p0[0]) < 1e-16 and abs(r.p1[0]) < 1e-16
    assert r.m0 == pytest.approx(1.25, rel=4e-16) and r.m1 == pytest.approx(1.25, rel=4e-16)
    # separating along n: no collision, states kept
    r = relcol.collide(1.0, [-1.0, 0], 1.0, [1.0, 0], [1.0, 0])
    assert not r.collided and r.p0[0] == -1.0


def test_shapes_and_broadcasting():
    out = relcol.collide(1.0, np.zeros((5, 2)) + [1, 0], [1, 2, 3, 4, 5], [0, 0], [1, 0])
    assert out.p0.shape == (5, 2) and out.m1.shape == (5,) and out.collided.all()
    with pytest.raises(ValueError):
        relcol.collide(1.0, [1, 0], 1.0, [0, 0, 0], [1, 0])


def test_errors_carry_the_library_message():
    m0, p0, m1, p1, n = random_pairs(10, 1.0)
    m1[6] = -2.0
    with pytest.raises(relcol.RelcolError) as e:
        relcol.collide(m0, p0, m1, p1, n, c=1.0)
    assert e.value.code == -3 and e.value.index == 6 and e.value.name == "RC_EMASS"
    assert relcol.strerror(-3) in str(e.value)
    n[3] = 0
    m1[6] = 1.0
    with pytest.raises(relcol.RelcolError, match="contact normal has zero length") as e:
        relcol.collide(m0, p0, m1, p1, n, c=1.0)
    assert e.value.index == 3
    with pytest.raises(relcol.RelcolError, match="restitution must be in") as e:
        relcol.collide(m0, p0, m1, p1, n, eps=2)
    assert e.value.index is None
    with pytest.raises(relcol.RelcolError, match=r"c must be > 0"):
        relcol.collide(1, [1], 1, [0], [1], c=-1)
    with pytest.raises(relcol.RelcolError, match="zmf, cm-isotropic.*unknown name"):
        relcol.collide(1, [1], 1, [0], [1], law="nope")
    with pytest.raises(relcol.RelcolError, match="speed must be < c"):
        relcol.momentum(1.0, [1.5, 0], c=1.0)
