"""relcol.soft_collide: the soft reference converges to the hard zmf law and keeps its
invariants."""
import numpy as np
import pytest

import relcol


@pytest.mark.parametrize("eps", [1.0, 0.5])
def test_soft_head_on_approaches_hard_law(eps):
    m = np.array([1.0, 2.0])
    p = relcol.momentum(m, np.array([[0.6, 0], [-0.3, 0]]), 1.0)
    x = np.array([[0.0, 0], [2.5, 0]])
    soft = relcol.soft_collide(m, p, x, 1.0, c=1.0, eps=eps, stiffness=1e7, rtol=1e-11)
    hard = relcol.collide(m[0], p[0], m[1], p[1], soft.normal, c=1.0, eps=eps)
    assert soft.finished and soft.n_contacts == 1
    # the soft outcome differs from the hard one by O(contact time x speed / r), about
    # 1/sqrt(stiffness) ~ 3e-4 here: 3e-3 of the momentum scale is a real check
    assert np.allclose(soft.p[0], hard.p0, atol=3e-3 * np.abs(p).max())
    assert soft.m[0] == pytest.approx(hard.m0, rel=3e-3)
    # momentum exactly (Newton's third law in the force), energy to the stepper's tolerance
    assert np.allclose(soft.p.sum(axis=0), p.sum(axis=0), atol=1e-12)
    assert soft.energy_error < 1e-6
    if eps < 1:
        assert (soft.u_int > 0).all()
    else:
        # elastic: no heat beyond the stepper's energy error (relative to the kinetic energy)
        assert np.abs(soft.u_int).max() < 1e-8 * relcol.kinetic_energy(m, p, 1.0).sum()


def test_soft_errors():
    with pytest.raises(relcol.RelcolError, match="shapes overlap"):
        relcol.soft_collide([1, 1], [[1, 0], [0, 0]], [[0, 0], [1, 0]], 1.0)
    with pytest.raises(relcol.RelcolError, match="stepper 'euler'"):
        relcol.soft_collide([1, 1], [[1, 0], [0, 0]], [[0, 0], [3, 0]], 1.0, stepper="euler")
    assert "cvode-bdf" in relcol.steppers()
