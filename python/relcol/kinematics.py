"""Kinematics over numpy arrays, in the library's conventions: a ball is its rest mass m
and momentum p; M = sqrt(m^2 + p^2/c^2), v = p / M; c = inf is the classical limit of the
same formulas (1/c^2 = 0). Vectors are arrays whose last axis holds 1 to 3 components."""
import numpy as np

from ._relcol import ffi, lib
from .errors import RelcolError, check, shape_error


def _args(func, m, p, pname="p"):
    """m and p (or v) as float arrays, p's last axis 1 to 3 components and m a number or
    one a vector (p.shape[:-1]); ValueError naming the argument otherwise."""
    p = np.asarray(p, dtype=float)
    m = np.asarray(m, dtype=float)
    if p.ndim == 0 or not 1 <= p.shape[-1] <= 3:
        raise shape_error(func, pname, p.shape, "vectors of 1 to 3 components, (..., d)")
    if m.shape not in ((), p.shape[:-1]):
        raise shape_error(func, "m", m.shape, "a number or %s like %s without its last axis"
                          % (p.shape[:-1], pname))
    return m, p


def inv_c2(c):
    """1/c^2 as the library takes it (c > 0, or inf); RelcolError otherwise."""
    out = ffi.new("double *")
    check(lib.rc_inv_c2(float(c), out), "c = %r" % (c,))
    return out[0]


def _check_balls(m, p, what):
    """Each (m, p) as the library's rc_particle_check takes it (0 < m < inf, finite p):
    numpy screens the arrays for the balls it could refuse, and the first of them goes
    through rc_particle_check itself, whose code is raised, naming the ball's field."""
    m, p = _args(what, m, p)
    ms = np.broadcast_to(m, p.shape[:-1]).ravel()
    ps = p.reshape(-1, p.shape[-1])
    suspect = ~(np.isfinite(ms) & (ms > 0) & np.all(np.isfinite(ps), axis=1))
    b = ffi.new("rc_particle *")
    for i in np.flatnonzero(suspect)[:1]:
        b.m = ms[i]
        q = [0.0, 0.0, 0.0]
        q[:ps.shape[-1]] = ps[i]
        b.p.x, b.p.y, b.p.z = q
        st = lib.rc_particle_check(b)
        if st != 0:
            one = ms.size == 1
            name = "m" if not (np.isfinite(ms[i]) and ms[i] > 0) else "p"
            raise RelcolError(st, what, None if one else int(i),
                              name if one else "%s[%d]" % (name, i))
    return m, p


def _mass_rel(m, p, c, func):
    m, p = _check_balls(m, p, func)
    return m, p, np.sqrt(m ** 2 + np.sum(p * p, axis=-1) * inv_c2(c))


def mass_rel(m, p, c=np.inf):
    """M = E/c^2 = sqrt(m^2 + |p|^2/c^2) (m classically)."""
    return _mass_rel(m, p, c, "mass_rel")[2]


def velocity(m, p, c=np.inf):
    """v = p / M."""
    m, p, M = _mass_rel(m, p, c, "velocity")
    return p / M[..., None]


def gamma(m, p, c=np.inf):
    """Lorentz factor M / m."""
    m, p, M = _mass_rel(m, p, c, "gamma")
    return M / m


def kinetic_energy(m, p, c=np.inf):
    """(gamma - 1) m c^2 = |p|^2 / (M + m) without cancellation (|p|^2 / 2m classically)."""
    m, p, M = _mass_rel(m, p, c, "kinetic_energy")
    return np.sum(p * p, axis=-1) / (M + m)


def momentum(m, v, c=np.inf):
    """p = gamma m v from velocities, |v| < c (RelcolError RC_ESPEED otherwise).
    1 - v^2/c^2 is formed as (1 - |v|/c)(1 + |v|/c), which keeps its relative accuracy
    near c where 1 - v^2/c^2 would cancel."""
    m, v = _args("momentum", m, v, "v")
    # (the first bad ball, named as rc_particle_check and rc_gamma_from_velocity would)
    mm = np.broadcast_to(m, v.shape[:-1]).ravel()
    vv = v.reshape(-1, v.shape[-1])
    at = lambda k, i: k if mm.size == 1 else "%s[%d]" % (k, i)
    for code, bad, k in ((-2, ~np.isfinite(mm), "m"), (-2, ~np.all(np.isfinite(vv), axis=1), "v"),
                         (-3, ~(mm > 0), "m")):
        if bad.any():
            i = int(np.argmax(bad))
            raise RelcolError(code, "momentum", None if mm.size == 1 else i, at(k, i))
    beta = np.sqrt(np.sum(v * v, axis=-1) * inv_c2(c))
    if np.any(beta >= 1):
        i = int(np.argmax(np.ravel(beta) >= 1))
        raise RelcolError(-4, "momentum", None if mm.size == 1 else i, at("v", i))
    g = 1 / np.sqrt((1 - beta) * (1 + beta))
    return (m * g)[..., None] * v
