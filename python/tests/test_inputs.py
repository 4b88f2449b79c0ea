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


@pytest.mark.parametrize("fn", [relcol.mass_rel, relcol.gamma, relcol.velocity,
                                relcol.kinetic_energy, relcol.momentum])
def test_kinematics_shapes_named(fn):
    # m of another length than p's vectors was a numpy broadcast error (or, for momentum,
    # a silently broadcast result); a 4-component vector was taken
    name = "v" if fn is relcol.momentum else "p"
    with pytest.raises(ValueError, match=r"%s: m: has shape \(3,\)" % fn.__name__):
        fn([1.0, 1.0, 1.0], np.zeros((2, 3)) + 0.1, c=1)
    with pytest.raises(ValueError, match=r"%s: %s: has shape \(2, 4\)" % (fn.__name__, name)):
        fn(1.0, np.zeros((2, 4)), c=1)
    with pytest.raises(relcol.RelcolError, match=r"%s: m\[1\]: rest mass must be > 0"
                       % fn.__name__) as e:
        fn([1.0, -1.0], np.zeros((2, 3)) + 0.1, c=1)
    assert e.value.field == "m[1]" and e.value.index == 1
    with pytest.raises(relcol.RelcolError, match=r"%s: %s\[0\]: not a finite" % (fn.__name__, name)):
        fn([1.0, 1.0], np.array([[math.nan, 0, 0], [0, 0, 0.1]]), c=1)


def test_collide_fields_named():
    p = np.zeros((4, 3))
    p[:, 0] = 0.5
    n = np.tile([1.0, 0, 0], (4, 1))
    m = np.ones(4)
    with pytest.raises(relcol.RelcolError, match=r"collide \(item 3\)|collide: m1\[3\]: rest mass"):
        relcol.collide(m, p, np.array([1, 1, 1, -1.0]), -p, n, c=2)
    cases = [(dict(m1=np.array([1, 1, 1, -1.0])), "m1[3]", "RC_EMASS"),
             (dict(p0=np.where(np.arange(4)[:, None] == 2, np.nan, p)), "p0[2]", "RC_ENONFINITE"),
             (dict(n=np.where(np.arange(4)[:, None] == 1, 0.0, n)), "n[1]", "RC_EZERONORMAL"),
             (dict(c=np.array([2, -1, 2, 2.0])), "c[1]", "RC_ESPEEDOFLIGHT"),
             (dict(eps=np.array([1, 1, 1, 1.5])), "eps[3]", "RC_ERESTITUTION"),
             (dict(eps=1.5), "eps", "RC_ERESTITUTION"),
             (dict(c=0.0), "c", "RC_ESPEEDOFLIGHT")]
    for change, field, code in cases:
        args = dict(m0=m, p0=p, m1=m, p1=-p, n=n, c=2.0, eps=1.0)
        args.update(change)
        with pytest.raises(relcol.RelcolError) as e:
            relcol.collide(**args)
        assert (e.value.field, e.value.name) == (field, code), (change, str(e.value))
        assert field in str(e.value)
    # c and eps as arrays: pair i equals the pair collided alone at c[i], eps[i]
    cs, es = np.array([1.5, 3.0, np.inf, 2.0]), np.array([1.0, 0.5, 0.8, 0.0])
    out = relcol.collide(m, p, m, -p, n, c=cs, eps=es)
    for i in range(4):
        one = relcol.collide(1.0, p[i], 1.0, -p[i], n[i], c=cs[i], eps=es[i])
        assert np.array_equal(out.p0[i], one.p0) and out.m1[i] == one.m1
    with pytest.raises(ValueError, match=r"collide: c: has shape \(3,\)"):
        relcol.collide(m, p, m, -p, n, c=[1, 2, 3])
