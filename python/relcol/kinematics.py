"""Kinematics over numpy arrays, in the library's conventions: a ball is its rest mass m
and momentum p; M = sqrt(m^2 + p^2/c^2), v = p / M; c = inf is the classical limit of the
same formulas (1/c^2 = 0). Vectors are arrays whose last axis holds 1 to 3 components."""
import numpy as np

from ._relcol import ffi, lib
from .errors import RelcolError, check


def inv_c2(c):
    """1/c^2 as the library takes it (c > 0, or inf); RelcolError otherwise."""
    out = ffi.new("double *")
    check(lib.rc_inv_c2(float(c), out), "c = %r" % (c,))
    return out[0]


def _check_balls(m, p, what):
    """Each (m, p) through the library's rc_particle_check (0 < m < inf, finite p): the
    check the C functions make, not a copy of it; RelcolError naming the first bad one."""
    p = np.asarray(p, dtype=float)
    ms = np.broadcast_to(np.asarray(m, float), p.shape[:-1]).ravel()
    ps = p.reshape(-1, p.shape[-1]) if p.ndim else p.reshape(1, 1)
    b = ffi.new("rc_particle *")
    for i in range(ms.size):
        b.m = ms[i]
        q = [0.0, 0.0, 0.0]
        q[:min(3, ps.shape[-1])] = ps[i][:3]
        b.p.x, b.p.y, b.p.z = q
        st = lib.rc_particle_check(b)
        if st != 0:
            raise RelcolError(st, what, i if ms.size > 1 else None)


def mass_rel(m, p, c=np.inf):
    """M = E/c^2 = sqrt(m^2 + |p|^2/c^2) (m classically)."""
    p = np.asarray(p, dtype=float)
    _check_balls(m, p, "mass_rel")
    return np.sqrt(np.asarray(m, float) ** 2 + np.sum(p * p, axis=-1) * inv_c2(c))


def velocity(m, p, c=np.inf):
    """v = p / M."""
    p = np.asarray(p, dtype=float)
    return p / mass_rel(m, p, c)[..., None]


def gamma(m, p, c=np.inf):
    """Lorentz factor M / m."""
    return mass_rel(m, p, c) / np.asarray(m, float)


def kinetic_energy(m, p, c=np.inf):
    """(gamma - 1) m c^2 = |p|^2 / (M + m) without cancellation (|p|^2 / 2m classically)."""
    p = np.asarray(p, dtype=float)
    return np.sum(p * p, axis=-1) / (mass_rel(m, p, c) + np.asarray(m, float))


def momentum(m, v, c=np.inf):
    """p = gamma m v from velocities, |v| < c (RelcolError RC_ESPEED otherwise).
    1 - v^2/c^2 is formed as (1 - |v|/c)(1 + |v|/c), which keeps its relative accuracy
    near c where 1 - v^2/c^2 would cancel."""
    v = np.asarray(v, dtype=float)
    m = np.asarray(m, dtype=float)
    if not (np.all(np.isfinite(v)) and np.all(np.isfinite(m))):
        raise RelcolError(-2, "momentum")
    if np.any(m <= 0):
        raise RelcolError(-3, "momentum")
    beta = np.sqrt(np.sum(v * v, axis=-1) * inv_c2(c))
    if np.any(beta >= 1):
        raise RelcolError(-4, "momentum", int(np.argmax(np.ravel(beta) >= 1)))
    g = 1 / np.sqrt((1 - beta) * (1 + beta))
    return (m * g)[..., None] * v
