"""relcol.toi: the closed form for spheres, frames by name, misses and overlaps."""
import math

import numpy as np
import pytest

import relcol


def test_spheres_head_on_closed_form():
    # classical: gap 3 - 2 closing at 1.5: contact at t = 1/1.5
    c = relcol.toi([0, 0], 1, 1, [1.0, 0], [3, 0], 1, 1, [-0.5, 0])
    assert c.hit and c.t == pytest.approx(1 / 1.5, rel=1e-15)
    assert np.allclose(c.n, [1, 0], atol=1e-15) and c.x[0] == pytest.approx(1 + 1 / 1.5, rel=1e-15)


def test_contracted_table_frame_later_than_spheres():
    # at c = 1 a ball moving at 0.8 c is half as thick along x: contact comes later
    p = relcol.momentum(1, [0.8, 0], 1)
    sphere = relcol.toi([0, 0], 1, 1, p, [4, 0], 1, 1, [0, 0], c=1, frame="sphere")
    table = relcol.toi([0, 0], 1, 1, p, [4, 0], 1, 1, [0, 0], c=1, frame="table")
    assert sphere.t == pytest.approx(2 / 0.8, rel=1e-14)
    # the centre must come within r/gamma + r = 1.6 of ball 1: t = 2.4 / 0.8
    assert table.t == pytest.approx(2.4 / 0.8, rel=1e-12)


def test_arrays_misses_and_frames():
    x1 = np.array([[3, 0], [3, 5], [3, 0.5]])
    out = relcol.toi([0, 0], 1, 1, [1.0, 0], x1, 1, 1, [0, 0], c=2, frame="zmf")
    assert list(out.hit) == [True, False, True]
    assert math.isinf(out.t[1]) and np.isnan(out.n[1]).all()
    assert {f.name for f in relcol.frames()} >= {"table", "zmf", "sphere"}
    assert [f.covariant for f in relcol.frames() if f.name == "zmf"] == [True]


def test_overlap_and_unknown_frame_raise():
    with pytest.raises(relcol.RelcolError, match="shapes overlap") as e:
        relcol.toi([[0, 0], [0, 0]], 1, 1, [1, 0], [[3, 0], [1, 0]], 1, 1, [0, 0])
    assert e.value.index == 1 and e.value.code == -8
    with pytest.raises(relcol.RelcolError, match="frame 'lab'.*table, zmf, sphere"):
        relcol.toi([0, 0], 1, 1, [1, 0], [3, 0], 1, 1, [0, 0], frame="lab")
