"""relcol.collide with shared c and eps goes through rc_collide_columns (its checks a block
of 256 pairs at a time, branch-free, then the kernels): every pair to the bit as the
library's rc_collide of that pair alone, in 1, 2 and 3 dimensions and from strided
(non-contiguous) arrays; one bad pair anywhere (inside a later block too) raises the code
rc_collide gives that pair, with its index; a spare output block is never handed out
while a result still uses it."""
import math

import numpy as np
import pytest

import relcol
from relcol import _ffi as ffi, _lib as lib


def pairs(n, d, seed):
    rng = np.random.default_rng(seed)
    m0 = np.exp(rng.uniform(-2, 2, n))
    m1 = np.exp(rng.uniform(-2, 2, n))
    p0, p1 = rng.normal(size=(n, d)), rng.normal(size=(n, d))
    nn = rng.normal(size=(n, d))
    return m0, p0, m1, p1, nn


def one(law, c, eps, m0, p0, m1, p1, n):
    d = len(p0)
    prm = ffi.new("rc_collision_params *", lib.rc_collision_params_default())
    prm.c, prm.eps = c, eps
    a, b = ffi.new("rc_particle *"), ffi.new("rc_particle *")
    pad = lambda v: list(v) + [0.0] * (3 - d)
    a.m, b.m = m0, m1
    a.p.x, a.p.y, a.p.z = pad(p0)
    b.p.x, b.p.y, b.p.z = pad(p1)
    nv = ffi.new("rc_vec3 *")
    nv.x, nv.y, nv.z = pad(n)
    rc = lib.rc_collide(lib.rc_law_find(law.encode()), prm, a, b, nv[0])
    return rc, a.m, [a.p.x, a.p.y, a.p.z][:d], b.m, [b.p.x, b.p.y, b.p.z][:d]


@pytest.mark.parametrize("d", [1, 2, 3])
@pytest.mark.parametrize("law,c", [("zmf", 1.0), ("zmf", math.inf), ("cm-isotropic", 2.0)])
def test_every_pair_as_rc_collide(d, law, c):
    n = 700
    m0, p0, m1, p1, nn = pairs(n, d, 7 + d)
    # strided views: every other row of twice as many
    big = [np.repeat(a, 2, axis=0) for a in (m0, p0, m1, p1, nn)]
    views = [a[::2] for a in big]
    assert not views[1].flags.c_contiguous
    out = relcol.collide(*views, c=c, eps=0.7, law=law)
    for i in range(0, n, 7):
        rc, a_m, a_p, b_m, b_p = one(law, c, 0.7, m0[i], p0[i], m1[i], p1[i], nn[i])
        assert out.collided[i] == (rc == 0)
        assert (out.m0[i], list(out.p0[i]), out.m1[i], list(out.p1[i])) == (a_m, a_p, b_m, b_p)


BAD = [("m0", math.nan), ("m1", -1.0), ("p0", math.inf), ("p1", 1e200), ("n", 0.0),
       ("n", math.nan), ("m0", 1e300)]


@pytest.mark.parametrize("where", [0, 255, 256, 600])
@pytest.mark.parametrize("field,value", BAD)
def test_first_bad_pair_named(where, field, value):
    n, d = 700, 3
    arrays = dict(zip(("m0", "p0", "m1", "p1", "n"), pairs(n, d, 11)))
    a = arrays[field]
    if a.ndim == 1:
        a[where] = value
    elif field == "n" and value == 0.0:
        a[where] = 0.0
    else:
        a[where, 1] = value
    if field == "m0" and value == 1e300:  # m^2 overflows: the pair's check, not the ball's
        arrays["p0"][where] = 1e160
    rc = one("zmf", 1.0, 0.5, arrays["m0"][where], arrays["p0"][where], arrays["m1"][where],
             arrays["p1"][where], arrays["n"][where])[0]
    assert rc < 0
    with pytest.raises(relcol.RelcolError) as e:
        relcol.collide(arrays["m0"], arrays["p0"], arrays["m1"], arrays["p1"], arrays["n"],
                       c=1.0, eps=0.5)
    assert (e.value.code, e.value.index) == (rc, where)


def test_spare_block_not_shared():
    n = 100000  # (above the spare blocks' 1 MB floor)
    m0, p0, m1, p1, nn = pairs(n, 3, 3)
    first = relcol.collide(m0, p0, m1, p1, nn, c=1.0, eps=0.5)
    kept = first.p1.copy()
    held = first.p1
    del first
    for _ in range(3):
        other = relcol.collide(m0, 2 * p0, m1, p1, nn, c=1.0, eps=0.5)
        assert not np.shares_memory(other.p0, held)
    assert held.tobytes() == kept.tobytes()
