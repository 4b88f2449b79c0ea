"""The package refuses what the C library refuses (issue 37 items 5 and 8): a negative or
NaN mass, a NaN momentum, an explicit NaN impact angle, and 1-D pairs so far apart that
the doubles of their positions cannot resolve the radii (RC_ESCALE, not x = NaN)."""
import math

import numpy as np
import pytest

import relcol


@pytest.mark.parametrize("fn", [relcol.gamma, relcol.kinetic_energy, relcol.velocity])
@pytest.mark.parametrize("m, p, code", [(-1, [0.5], "RC_EMASS"), (0, [0.5], "RC_EMASS"),
                                        (math.nan, [0.5], "RC_ENONFINITE"),
                                        (1, [math.nan], "RC_ENONFINITE"),
                                        (1, [math.inf], "RC_ENONFINITE")])
def test_kinematics_refuse_bad_balls(fn, m, p, code):
    with pytest.raises(relcol.RelcolError) as e:
        fn(m, p, c=1)
    assert e.value.name == code


def test_kinematics_name_the_bad_ball_in_an_array():
    with pytest.raises(relcol.RelcolError) as e:
        relcol.gamma([1, 1, -2], [[0.1], [0.2], [0.3]], c=1)
    assert e.value.index == 2
    # and good balls still give the closed form: gamma = sqrt(1 + p^2) at m = c = 1
    assert relcol.gamma(1, [0.75], c=1) == pytest.approx(1.25, rel=1e-15)


def test_collide_refuses_nan_alpha():
    with pytest.raises(relcol.RelcolError) as e:
        relcol.collide(1, [0.5, 0], 1, [-0.5, 0], [1, 0], c=2, law="cm-isotropic", alpha=math.nan)
    assert e.value.name == "RC_ENONFINITE"


@pytest.mark.parametrize("D", [1e13, 1e17, 1e30])
def test_toi_far_apart_refused(D):
    with pytest.raises(relcol.RelcolError) as e:
        relcol.toi([0.0], 1, 1, [0.5], [D], 1, 1, [0.0])
    assert e.value.name == "RC_ESCALE"


def test_toi_far_but_resolved():
    # 1e12 radii apart: t = (D - 2) / 0.5 classically, to round-off
    c = relcol.toi([0.0], 1, 1, [0.5], [1e12], 1, 1, [0.0])
    assert c.hit and c.t == pytest.approx((1e12 - 2) / 0.5, rel=1e-12)
    assert np.all(np.isfinite(c.x)) and c.n[0] == pytest.approx(1.0, rel=1e-12)
