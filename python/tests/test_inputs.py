"""Every input checked (issue 38, item 3): array lengths and shapes of every function's
arguments raise naming the argument, and errors name the field that is wrong in the
library's or the scenario reader's words. Each case here passed silently or named the
wrong field before (Gas1D read past the end of its arrays)."""
import math

import numpy as np
import pytest

import relcol


@pytest.mark.parametrize("x, m, p, name", [
    ([0, 1, 2], [1, 1, 1], [0.1, 0], "p"),          # the case: read past the end
    ([0.1, 0.2, 0.3, 0.4, 0.5], 1.0, [0.0], "p"),    # 5 positions, 1 momentum
    ([0.1, 0.2], [1, 1, 1], [0, 0], "m"),
    ([[0.1, 0.2]], 1.0, [0, 0], "x"),
    ([], 1.0, [], "x"),
])
def test_gas1d_lengths(x, m, p, name):
    with pytest.raises(ValueError, match=r"Gas1D: %s: has shape" % name):
        relcol.Gas1D(x, m, p)


def test_gas1d_fields_named():
    with pytest.raises(relcol.RelcolError, match=r"Gas1D: m\[1\]: rest mass must be > 0") as e:
        relcol.Gas1D([0.1, 0.2], [1, -1], [0, 0])
    assert e.value.field == "m[1]"
    with pytest.raises(relcol.RelcolError, match=r"Gas1D: length: invalid argument"):
        relcol.Gas1D([0.1, 0.2], 1, [0, 0], length=-1)
    with pytest.raises(relcol.RelcolError, match=r"Gas1D: x\[1\]: invalid argument"):
        relcol.Gas1D([0.5, 0.2], 1, [0, 0])
    with pytest.raises(relcol.RelcolError, match=r"Gas1D: p\[0\]: not a finite number"):
        relcol.Gas1D([0.1, 0.2], 1, [math.nan, 0])
    with pytest.raises(relcol.RelcolError, match=r"Gas1D: c: c must be > 0"):
        relcol.Gas1D([0.1, 0.2], 1, [0, 0], c=-1)
    with pytest.raises(ValueError, match=r"Gas1D: length: has shape \(2,\)"):
        relcol.Gas1D([0.1, 0.2], 1, [0, 0], length=[1, 2])


def test_sim_fields_named():
    # a radius 0 was reported as "balls[0].v: rest mass must be > 0"; a negative box and a
    # ball outside the box as "invalid argument": now the scenario reader's paths
    with pytest.raises(relcol.ScenarioError, match=r"balls\[0\]\.r: radius must be > 0") as e:
        relcol.Sim(dim=2, box=[4, 4], c=2, balls=[{"x": [1, 1], "v": [0.5, 0], "r": 0}])
    assert e.value.path == "balls[0].r"
    with pytest.raises(relcol.ScenarioError, match=r"box: edge 0 must be > 0"):
        relcol.Sim(dim=2, box=[-4, 4], balls=[{"x": [1, 1], "r": 0.5}])
    with pytest.raises(relcol.ScenarioError,
                       match=r"balls\[0\]\.x: the centre is not inside the box along axis 0"):
        relcol.Sim(dim=2, box=[4, 4], balls=[{"x": [5, 1], "r": 0.5}])
    with pytest.raises(relcol.ScenarioError, match=r"balls\[0\]: the ball's shape is not inside"):
        relcol.Sim(dim=2, box=[4, 4], balls=[{"x": [0.2, 1], "r": 0.5}])
    with pytest.raises(relcol.ScenarioError, match=r"balls\.v: has shape \(1, 2\)"):
        relcol.Sim(dim=2, box=[4, 4], balls={"x": [[1, 1], [3, 3]], "v": [[0, 0]], "r": 0.5})
    with pytest.raises(relcol.ScenarioError, match=r"balls\.r: has shape \(3,\)"):
        relcol.Sim(dim=2, box=[4, 4], balls={"x": [[1, 1], [3, 3]], "r": [0.5, 0.5, 0.5]})
    with pytest.raises(relcol.ScenarioError, match=r"balls\[0\]\.x: has 3 components, the "
                                                   r"scenario is 2-D"):
        relcol.Sim(dim=2, box=[4, 4], balls={"x": [[1, 1, 1]], "r": 0.5})
    with pytest.raises(relcol.ScenarioError, match=r"c: must be > 0"):
        relcol.Sim(dim=2, box=[4, 4], c=-1, balls={"x": [[1, 1]], "r": 0.5})
    with pytest.raises(relcol.ScenarioError, match=r"balls\[0\]\.x: component 0 is not a finite"):
        relcol.Sim(dim=2, box=[4, 4], balls={"x": [[math.nan, 1]], "r": 0.5})


def test_gas_init_fields_named():
    # n = -5 raised OverflowError
    with pytest.raises(relcol.ScenarioError, match=r"gas_init: generate\.n: must be a whole"):
        relcol.gas_init(2, -5, 1.0, 0.2, 0.5, c=1.0)
    with pytest.raises(relcol.ScenarioError, match=r"generate\.v_rms: must be in \[0, c\)"):
        relcol.gas_init(2, 10, 1.0, 0.2, 1.5, c=1.0)
    with pytest.raises(relcol.ScenarioError, match=r"dim: must be 2 or 3"):
        relcol.gas_init(4, 10, 1.0, 0.2, 0.5)


def test_collide_toi_soft_shapes():
    p = np.zeros((4, 3))
    with pytest.raises(ValueError, match="do not broadcast"):
        relcol.collide(np.ones(3), p, 1.0, p, np.ones((4, 3)))
    with pytest.raises(ValueError, match=r"collide: p1: has shape \(3,\), expected 2 components"):
        relcol.collide(1.0, np.zeros(2), 1.0, np.zeros(3), np.ones(3))
    with pytest.raises(ValueError, match=r"toi: r0: has shape \(2,\)"):
        relcol.toi(np.zeros((3, 2)), [1, 1], 1, np.zeros((3, 2)), np.ones((3, 2)) * 5, 1, 1,
                   np.zeros((3, 2)))
    with pytest.raises(ValueError, match=r"soft_collide: m: has shape \(3,\)"):
        relcol.soft_collide([1, 1, 1], np.zeros((2, 2)), np.zeros((2, 2)), 1.0)
    with pytest.raises(ValueError, match=r"soft_collide: r: has shape \(3,\)"):
        relcol.soft_collide(1.0, np.zeros((2, 2)), np.zeros((2, 2)), [1, 1, 1])
