"""Two-ball collisions over numpy arrays of pairs, through the library's law table.

collide() copies each quantity into one contiguous column and makes one call,
rc_collide_many, which checks every pair as rc_collide does and runs the law's kernel over
all of them in place: the per-pair cost is the C kernel's, not Python's."""
import collections
import math

import numpy as np

from ._relcol import ffi, lib
from .errors import RelcolError, check

Law = collections.namedtuple("Law", "name summary uses_angle keeps_zmf_energy")
Law.__doc__ = """A collision law of the library's table (relcol/law.h)."""

Collision = collections.namedtuple("Collision", "m0 p0 m1 p1 collided")
Collision.__doc__ = """The outcome of collide(): rest masses and momenta after the
collision (arrays shaped as the input; pairs that did not collide keep their states) and
`collided`, True where the balls approached along the normal and the law acted."""


def _table(array):
    out, i = [], 0
    while array[i] != ffi.NULL:
        out.append(array[i])
        i += 1
    return out


def laws():
    """The built-in collision laws, in the library's order."""
    return [Law(ffi.string(l.name).decode(), ffi.string(l.summary).decode(),
                bool(l.uses_angle), bool(l.keeps_zmf_energy)) for l in _table(lib.rc_laws)]


def find_law(name):
    """The library's law called name (RelcolError RC_EUNKNOWN naming the known ones)."""
    law = lib.rc_law_find(str(name).encode())
    if law == ffi.NULL:
        raise RelcolError(-11, "law %r (known: %s)" % (name, ", ".join(l.name for l in laws())))
    return law


def _vectors(a, what):
    a = np.asarray(a, dtype=float)
    if a.ndim not in (1, 2) or not 1 <= a.shape[-1] <= 3:
        raise ValueError("%s: expected vectors of 1 to 3 components, shape (3,) or (N, 3), "
                         "got shape %s" % (what, a.shape))
    return a


def collide(m0, p0, m1, p1, n, c=math.inf, eps=1.0, law="zmf", alpha=None, azimuth=0.0):
    """Collide pairs of balls: ball 0 (rest mass m0, momentum p0) with ball 1 (m1, p1)
    along the contact normal n (from ball 0 to ball 1; any length, it is normalised).

    Vectors have 1 to 3 components (the last axis); give one pair as (d,) vectors and
    scalar masses, or N pairs as (N, d) arrays and (N,) or scalar masses (they
    broadcast). c is the speed of light (inf: classical), eps the restitution in [0, 1],
    each one number or one per pair,
    law a name from laws(); alpha and azimuth the impact angle of laws that use one
    (cm-isotropic; None: the angle follows from n).

    Returns Collision(m0, p0, m1, p1, collided). Invalid input raises RelcolError with
    the library's reason and the index of the first bad pair.
    """
    lw = find_law(law)
    p0, p1, n = _vectors(p0, "p0"), _vectors(p1, "p1"), _vectors(n, "n")
    d = p0.shape[-1]
    if p1.shape[-1] != d or n.shape[-1] != d:
        raise ValueError("p0, p1 and n must have the same number of components "
                         "(%d, %d, %d)" % (d, p1.shape[-1], n.shape[-1]))
    m0, m1 = np.asarray(m0, dtype=float), np.asarray(m1, dtype=float)
    single = p0.ndim == 1 and p1.ndim == 1 and n.ndim == 1 and m0.ndim == 0 and m1.ndim == 0
    try:
        count = np.broadcast_shapes(m0.shape, m1.shape, p0.shape[:-1], p1.shape[:-1],
                                    n.shape[:-1])
    except ValueError:
        raise ValueError("the pairs' arrays do not broadcast: m0 %s, p0 %s, m1 %s, p1 %s, "
                         "n %s" % (m0.shape, p0.shape, m1.shape, p1.shape, n.shape)) from None
    if len(count) > 1:
        raise ValueError("masses must be scalars or (N,) arrays")
    npair = count[0] if count else 1
    # one contiguous column per quantity, as rc_collide_many takes them: copies that the
    # library collides in place (the caller's arrays are never changed)
    m0 = np.array(np.broadcast_to(m0, (npair,)), dtype=float, order="C")
    m1 = np.array(np.broadcast_to(m1, (npair,)), dtype=float, order="C")
    p0, p1 = (_columns(v, npair, d) for v in (p0, p1))
    # the normals are only read: used as they are when they already have the layout
    nn = n if (d == 3 and n.shape == (npair, 3) and n.flags.c_contiguous) else _columns(n, npair, d)
    prm = ffi.new("rc_collision_params *", lib.rc_collision_params_default())
    # (NaN is the library's "no angle given", which is said with None here: an explicit
    # NaN is refused as relcol-collide --alpha refuses it)
    if alpha is not None and math.isnan(float(alpha)):
        raise RelcolError(-2, "collide: alpha")
    prm.alpha = math.nan if alpha is None else float(alpha)
    prm.azimuth = float(azimuth)
    # c and eps: one number for every pair, or one per pair (they broadcast as the masses)
    cols = []
    for name, v in (("c", c), ("eps", eps)):
        a = np.asarray(v, dtype=float)
        if a.ndim == 0:
            cols.append((np.array([float(a)]), 0))
        elif a.shape == (npair,) or (a.ndim == 1 and len(a) == 1):
            cols.append((np.ascontiguousarray(np.broadcast_to(a, (npair,))), 1))
        else:
            raise ValueError("collide: %s: has shape %s, expected a number or (%d,) like the "
                             "pairs" % (name, a.shape, npair))
    (cc, sc), (ee, se) = cols
    status = np.zeros(npair, dtype=np.intc)
    hits = ffi.new("size_t *")
    bad = ffi.new("size_t *")
    rc = lib.rcpy_collide_many(lw, prm, npair, ffi.from_buffer("double[]", cc), sc,
                               ffi.from_buffer("double[]", ee), se,
                               _buf("double[]", m0), _buf("rc_vec3[]", p0),
                               _buf("double[]", m1), _buf("rc_vec3[]", p1),
                               ffi.from_buffer("rc_vec3[]", nn), _buf("int[]", status), hits, bad)
    if rc < 0:
        if sc == 0 and se == 0:
            prm.c, prm.eps = cc[0], ee[0]
            check(rc, "collide", int(bad[0]) if npair and _params_ok(prm) else None)
        check(rc, "collide", int(bad[0]) if npair else None)
    collided = status == lib.RC_OK
    if d < 3:
        p0, p1 = p0[:, :d], p1[:, :d]
    if single:
        return Collision(m0[0], p0[0], m1[0], p1[0], bool(collided[0]))
    return Collision(m0, p0, m1, p1, collided)


def _buf(ctype, a):
    return ffi.from_buffer(ctype, a, require_writable=True)


def _columns(v, npair, d):
    """(npair, 3) C-contiguous copy of (npair, d) or (d,) vectors, zeros beyond d."""
    if d == 3:
        return np.array(np.broadcast_to(v, (npair, 3)), dtype=float, order="C")
    out = np.zeros((npair, 3))
    out[:, :d] = v
    return out


def _params_ok(prm):
    """Whether the shared parameters pass the library's checks (so that a failure is the
    pair's): the same batch call with no pairs checks exactly those."""
    return lib.rc_collide_many(lib.rc_law_find(b"zmf"), prm, 0, ffi.NULL, ffi.NULL, ffi.NULL,
                               ffi.NULL, ffi.NULL, ffi.NULL, ffi.NULL, ffi.NULL) == 0
