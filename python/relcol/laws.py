"""Two-ball collisions over numpy arrays of pairs, through the library's law table.

collide() makes one C call over the caller's arrays at their strides (pyrelcol.c; with
shared c and eps the library's rc_collide_columns, which checks a block of pairs at a time
as rc_collide does, branch-free, then runs the law's kernel over it) into one output
block: the per-pair cost is the C loop's, not Python's."""
import collections
import math
import sys

import numpy as np

from ._relcol import ffi, lib
from .errors import RelcolError, check, check_field, shape_error

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


def _vectors(a, what, func="collide"):
    a = np.asarray(a, dtype=float)
    if a.ndim not in (1, 2) or not 1 <= a.shape[-1] <= 3:
        raise shape_error(func, what, a.shape, "vectors of 1 to 3 components, (d,) or (N, d)")
    return a


def _per_pair(name, a, npair, d=None):
    """a as a contiguous float64 array and its stride in elements a pair: 0 when one value
    (or one vector) serves every pair, 1 (d for vectors) when there is one a pair."""
    a = np.asarray(a, dtype=float)
    one, each = ((), (npair,)) if d is None else ((d,), (npair, d))
    if a.shape == one or a.shape == (1,) + one:
        return np.ascontiguousarray(a).reshape(-1), 0
    if a.shape == each:
        return np.ascontiguousarray(a), 1 if d is None else d
    raise shape_error("collide", name, a.shape, "%s or %s (one value, or one a pair)"
                      % (one if one else "a number", each))


def collide(m0, p0, m1, p1, n, c=math.inf, eps=1.0, law="zmf", alpha=None, azimuth=0.0):
    """Collide pairs of balls: ball 0 (rest mass m0, momentum p0) with ball 1 (m1, p1)
    along the contact normal n (from ball 0 to ball 1; any length, it is normalised).

    Vectors have 1 to 3 components (the last axis); give one pair as (d,) vectors and
    scalar masses, or N pairs as (N, d) arrays and (N,) or scalar masses (they
    broadcast). c is the speed of light (inf: classical), eps the restitution in [0, 1],
    each one number or one per pair ((N,) arrays: they broadcast as the masses),
    law a name from laws(); alpha and azimuth the impact angle of laws that use one
    (cm-isotropic; None: the angle follows from n).

    Every pair goes through the library's rc_collide, its checks and the law's kernel,
    in one C loop (pyrelcol.c). Returns Collision(m0, p0, m1, p1, collided). A wrong
    shape raises ValueError naming the argument; invalid input raises RelcolError with
    the library's reason, the first bad pair's index and the field, e.g. "m1[3]".
    """
    lw = find_law(law)
    p0, p1, n = _vectors(p0, "p0"), _vectors(p1, "p1"), _vectors(n, "n")
    d = p0.shape[-1]
    for name, v in (("p1", p1), ("n", n)):
        if v.shape[-1] != d:
            raise shape_error("collide", name, v.shape, "%d components like p0" % d)
    m0, m1 = np.asarray(m0, dtype=float), np.asarray(m1, dtype=float)
    cc, ee = np.asarray(c, dtype=float), np.asarray(eps, dtype=float)
    single = (p0.ndim == 1 and p1.ndim == 1 and n.ndim == 1 and m0.ndim == 0 and
              m1.ndim == 0 and cc.ndim == 0 and ee.ndim == 0)
    shapes = (("m0", m0.shape), ("m1", m1.shape), ("p0", p0.shape[:-1]),
              ("p1", p1.shape[:-1]), ("n", n.shape[:-1]), ("c", cc.shape), ("eps", ee.shape))
    for name, sh in shapes:
        if len(sh) > 1:
            raise shape_error("collide", name, sh if name in ("m0", "m1", "c", "eps") else
                              sh + (d,), "a number or (N,)" if name in ("m0", "m1", "c", "eps")
                              else "(d,) or (N, d)")
    # the pairs' count: the most common length given (ties: the first), so that the odd
    # argument out is the one named
    lengths = [sh[0] for _, sh in shapes if sh and sh[0] != 1]
    npair = max(lengths, key=lengths.count) if lengths else 1
    for name, sh in shapes:
        if sh and sh[0] not in (1, npair):
            want = "a number or (%d,)" % npair if name in ("m0", "m1", "c", "eps") else \
                "(%d,) or (%d, %d)" % (d, npair, d)
            raise ValueError("collide: %s: has shape %s, expected %s like the other arrays "
                             "(the pairs' arrays do not broadcast)" % (
                                 name, sh if name in ("m0", "m1", "c", "eps") else sh + (d,), want))
    prm = ffi.new("rc_collision_params *", lib.rc_collision_params_default())
    # (NaN is the library's "no angle given", which is said with None here: an explicit
    # NaN is refused as relcol-collide --alpha refuses it)
    if alpha is not None and math.isnan(float(alpha)):
        raise RelcolError(-2, "collide", field="alpha")
    prm.alpha = math.nan if alpha is None else float(alpha)
    prm.azimuth = float(azimuth)
    cols = [_per_pair("c", cc, npair), _per_pair("eps", ee, npair),
            _per_pair("m0", m0, npair), _per_pair("p0", p0, npair, d),
            _per_pair("m1", m1, npair), _per_pair("p1", p1, npair, d),
            _per_pair("n", n, npair, d)]
    if cols[0][1] == 0 and cols[1][1] == 0:
        # shared parameters checked once, by the library's batch call with no pairs: a
        # failure is then no pair's
        prm.c, prm.eps = float(cols[0][0][0]), float(cols[1][0][0])
        rc = lib.rc_collide_many(lw, prm, 0, ffi.NULL, ffi.NULL, ffi.NULL, ffi.NULL, ffi.NULL,
                                 ffi.NULL, ffi.NULL, ffi.NULL)
        check_field(rc, "collide", None, _PARAM_FIELD.get(rc))
    *out, status = _outputs(npair, d)
    hits = ffi.new("size_t *")
    bad = ffi.new("size_t *")
    args = []
    for a, stride in cols:
        args += [ffi.from_buffer("double[]", a), stride]
    rc = lib.rcpy_collide(lw, prm, npair, d, *args, *(_buf("double[]", o) for o in out),
                          _buf("int[]", status), hits, bad)
    if rc < 0:
        i = int(bad[0])
        check_field(rc, "collide", i, _pair_field(rc, i, cols, d))
    m0, p0, m1, p1 = out
    collided = status == lib.RC_OK
    if single:
        return Collision(m0[0], p0[0], m1[0], p1[0], bool(collided[0]))
    return Collision(m0, p0, m1, p1, collided)


# the shared parameter each of check_params' codes points at (law_table.c)
_PARAM_FIELD = {-6: "c", -5: "eps", -1: "alpha, azimuth"}


def _pair_field(rc, i, cols, d):
    """The argument of pair i that the library's code rc points at, found by the library's
    own checks of its pieces (rc_particle_check, rc_inv_c2); None for a law's failure."""
    (c, sc), (e, se), (m0, s0), (p0, q0), (m1, s1), (p1, q1), (n, sn) = \
        [(np.ravel(a), stride) for a, stride in cols]
    at = lambda name, stride: "%s[%d]" % (name, i) if stride else name
    b = ffi.new("rc_particle *")
    for mname, m, ms, pname, p, ps in (("m0", m0, s0, "p0", p0, q0), ("m1", m1, s1, "p1", p1, q1)):
        b.m = m[i * ms]
        v = list(p[i * ps:i * ps + d]) + [0.0] * (3 - d)
        b.p.x, b.p.y, b.p.z = v
        if lib.rc_particle_check(b) != 0:
            return at(mname, ms) if not (math.isfinite(b.m) and b.m > 0) else at(pname, ps)
    k = ffi.new("double *")
    if rc == -6 or lib.rc_inv_c2(float(c[i * sc]), k) != 0:
        return at("c", sc)
    if rc == -5:
        return at("eps", se)
    if rc == -7 or (rc == -2 and not np.all(np.isfinite(n[i * sn:i * sn + d]))):
        return at("n", sn)
    if rc == -2:  # m^2 + p^2/c^2 or |p0 + p1|^2 overflows
        return "%s, %s" % (at("p0", q0), at("p1", q1))
    if rc == -1:
        return "alpha, azimuth"
    return None


# Output blocks of earlier large calls, reused once every array of their result is gone
# (the block's only references are then this list's and the lookup's): fresh pages cost
# the kernel's zeroing of them, a third of a 10^6-pair call, that the C batch writing in
# place does not pay. The library writes every element of a result it returns.
_SPARE = []
_SPARE_MAX, _SPARE_MIN_BYTES = 2, 1 << 20


def _outputs(npair, d):
    """m0, p0, m1, p1 (float64; (npair,), (npair, d)) and status (intc, (npair,)),
    uninitialised views of one block."""
    nf = npair * (2 + 2 * d)
    nbytes = 8 * nf + np.dtype(np.intc).itemsize * npair
    block = None
    if nbytes >= _SPARE_MIN_BYTES:
        for b in _SPARE:
            # (3: the list's reference, b's and getrefcount's argument: no view alive)
            if b.nbytes == nbytes and sys.getrefcount(b) == 3:
                block = b
                break
        if block is None:
            block = np.empty(nbytes, dtype=np.uint8)
            _SPARE.append(block)
            if len(_SPARE) > _SPARE_MAX:
                del _SPARE[0]
    else:
        block = np.empty(nbytes, dtype=np.uint8)
    f = block[:8 * nf].view(np.float64)
    m0, p0 = f[:npair], f[npair:npair * (1 + d)].reshape(npair, d)
    m1, p1 = f[npair * (1 + d):npair * (2 + d)], f[npair * (2 + d):].reshape(npair, d)
    return m0, p0, m1, p1, block[8 * nf:].view(np.intc)


def _buf(ctype, a):
    return ffi.from_buffer(ctype, a, require_writable=True)
