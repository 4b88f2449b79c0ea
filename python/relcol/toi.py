"""Time of impact of two balls (Lorentz-contracted at finite c), with the contact frame
chosen by name from the library's frame table (relcol/toi.h): "table" (contact of the
table-frame shapes), "zmf" (found in the pair's zero-momentum frame: covariant),
"sphere" (contraction ignored)."""
import collections
import math

import numpy as np

from ._relcol import ffi, lib
from .errors import RelcolError, check, shape_error
from .laws import _table, _vectors

Frame = collections.namedtuple("Frame", "name summary contracted covariant wall_contracted")
Frame.__doc__ = """A contact frame of the library's table."""

Contact = collections.namedtuple("Contact", "t x n hit")
Contact.__doc__ = """The outcome of toi(): table time t of first contact (inf if none),
contact point x and unit normal n from ball 0 to ball 1 (NaN if none), and hit (True if
there is a contact in the future; grazing and separating pairs are misses)."""


def frames():
    """The built-in contact frames, in the library's order."""
    return [Frame(ffi.string(f.name).decode(), ffi.string(f.summary).decode(),
                  bool(f.contracted), bool(f.covariant), bool(f.wall_contracted))
            for f in _table(lib.rc_toi_frames)]


def find_frame(name):
    """The library's contact frame called name (RelcolError RC_EUNKNOWN otherwise)."""
    fr = lib.rc_toi_frame_find(str(name).encode())
    if fr == ffi.NULL:
        raise RelcolError(-11, "frame %r (known: %s)" % (name, ", ".join(f.name for f in frames())))
    return fr


def toi_params(c=math.inf, touch_tol=None, graze_tol=None, lambda_tol=None, max_iter=None):
    """rc_toi_params with the library's defaults for the tolerances left as None."""
    prm = ffi.new("rc_toi_params *", lib.rc_toi_params_default())
    prm.c = float(c)
    if touch_tol is not None:
        prm.touch_tol = float(touch_tol)
    if graze_tol is not None:
        prm.graze_tol = float(graze_tol)
    if lambda_tol is not None:
        prm.lambda_tol = float(lambda_tol)
    if max_iter is not None:
        prm.max_iter = int(max_iter)
    return prm


def _fill(ball, x, r, m, p, d):
    for k in range(d):
        setattr(ball.x, "xyz"[k], x[k])
        setattr(ball.p, "xyz"[k], p[k])
    ball.r = r
    ball.m = m


def toi(x0, r0, m0, p0, x1, r1, m1, p1, c=math.inf, frame="table", **tolerances):
    """First contact of ball 0 (centre x0, rest radius r0, rest mass m0, momentum p0, at
    table time 0) and ball 1, in the contact frame `frame`.

    Vectors have 1 to 3 components; one pair as (d,) vectors and scalars, or N pairs as
    (N, d) arrays and (N,) or scalar radii and masses (a loop over the library's rc_toi).
    tolerances: touch_tol, graze_tol, lambda_tol, max_iter (relcol/toi.h; defaults the
    library's). Returns Contact(t, x, n, hit); overlapping balls and invalid input raise
    RelcolError (RC_EOVERLAP, ...) naming the pair.
    """
    fr = find_frame(frame)
    prm = toi_params(c, **tolerances)
    vec = [_vectors(v, w) for v, w in ((x0, "x0"), (p0, "p0"), (x1, "x1"), (p1, "p1"))]
    d = vec[0].shape[-1]
    if any(v.shape[-1] != d for v in vec):
        raise ValueError("x0, p0, x1 and p1 must have the same number of components")
    sc = [np.asarray(s, dtype=float) for s in (r0, m0, r1, m1)]
    single = all(v.ndim == 1 for v in vec) and all(s.ndim == 0 for s in sc)
    rows = [v.shape[0] for v in vec if v.ndim == 2] + [a.shape[0] for a in sc if a.ndim == 1]
    npair = max(rows) if rows else 1
    for name, v in zip(("x0", "p0", "x1", "p1"), vec):
        if v.ndim == 2 and v.shape[0] != npair:
            raise shape_error("toi", name, v.shape, "(%d,) or (%d, %d)" % (d, npair, d))
    for name, a in zip(("r0", "m0", "r1", "m1"), sc):
        if a.ndim > 1 or (a.ndim == 1 and a.shape[0] != npair):
            raise shape_error("toi", name, a.shape, "a scalar or (%d,)" % npair)
    x0, p0, x1, p1 = (np.broadcast_to(v, (npair, d)) for v in vec)
    r0, m0, r1, m1 = (np.broadcast_to(s, (npair,)) for s in sc)
    ws = ffi.new("rc_toi_workspace **")
    check(lib.rc_toi_workspace_create(ws), "toi")
    a = ffi.new("rc_toi_ball *")
    b = ffi.new("rc_toi_ball *")
    out = ffi.new("rc_toi_contact *")
    t = np.full(npair, np.inf)
    xc = np.full((npair, d), np.nan)
    nc = np.full((npair, d), np.nan)
    try:
        for i in range(npair):
            _fill(a, x0[i], r0[i], m0[i], p0[i], d)
            _fill(b, x1[i], r1[i], m1[i], p1[i], d)
            rc = lib.rc_toi(fr, prm, a, b, ws[0], out)
            check(rc, "toi", None if single else i)
            if rc == lib.RC_OK:
                t[i] = out.t
                xc[i] = [out.x.x, out.x.y, out.x.z][:d]
                nc[i] = [out.n.x, out.n.y, out.n.z][:d]
    finally:
        lib.rc_toi_workspace_free(ws)
    hit = np.isfinite(t)
    if single:
        return Contact(float(t[0]), xc[0], nc[0], bool(hit[0]))
    return Contact(t, xc, nc, hit)
