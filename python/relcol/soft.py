"""The soft-sphere reference (relcol/soft.h): balls with a stiff spring-dashpot contact
under relativistic equations of motion, integrated by a stepper of the library's table
(CVODE BDF, GSL Runge-Kutta), the energy the dashpot takes becoming rest mass. As the
stiffness grows its outcome converges to the hard law (rc_law_zmf)."""
import collections
import math

import numpy as np

from ._relcol import ffi, lib
from .errors import RelcolError, check, shape_error
from .laws import _table

SHAPES = {"sphere": 0, "contracted": 1, "contracted-frozen": 2}

SoftResult = collections.namedtuple(
    "SoftResult", "m p x u_int t_end normal n_contacts n_shape_overlaps finished "
                  "energy_error momentum_error n_steps n_rhs")
SoftResult.__doc__ = """The outcome of soft_collide(): rest masses, momenta and positions
at table time t_end, the internal energy each ball gained (u_int), the table-frame normal
of the first contact, and the run's diagnostics (relcol/soft.h, rc_soft_result)."""


def steppers():
    """Names of the library's steppers."""
    return [ffi.string(s.name).decode() for s in _table(lib.rc_soft_steppers)]


def soft_collide(m, p, x, r, c=math.inf, eps=1.0, stiffness=1e6, rtol=1e-10,
                 stepper="cvode-bdf", shape="sphere", t_max=math.inf, max_steps=1000000):
    """Run n >= 2 balls (rest masses m (n,), momenta p and positions x (n, d), radii r)
    from table time 0 until no contact is left and every pair recedes (or t_max).

    eps in (0, 1] sets the dashpot, stiffness is the force per unit overlap, rtol the
    stepper's relative tolerance, shape "sphere", "contracted" or "contracted-frozen"
    (the reference the hard zmf law is the limit of). RelcolError on failure."""
    st = lib.rc_soft_stepper_find(str(stepper).encode())
    if st == ffi.NULL:
        raise RelcolError(-11, "stepper %r (known: %s)" % (stepper, ", ".join(steppers())))
    if shape not in SHAPES:
        raise RelcolError(-11, "shape %r (known: %s)" % (shape, ", ".join(SHAPES)))
    p = np.atleast_2d(np.asarray(p, dtype=float))
    x = np.atleast_2d(np.asarray(x, dtype=float))
    n, d = p.shape
    if x.shape != (n, d) or not 1 <= d <= 3:
        raise ValueError("p and x must both be (n, d) arrays with d in 1..3: %s, %s"
                         % (p.shape, x.shape))
    m, r = np.asarray(m, dtype=float), np.asarray(r, dtype=float)
    for name, a in (("m", m), ("r", r)):
        if a.shape not in ((), (n,)):
            raise shape_error("soft_collide", name, a.shape, "a scalar or (%d,) like p" % n)
    m = np.broadcast_to(m, (n,))
    r = np.ascontiguousarray(np.broadcast_to(r, (n,)))
    b = np.zeros((n, 4))
    b[:, 0] = m
    b[:, 1:1 + d] = p
    xx = np.zeros((n, 3))
    xx[:, :d] = x
    u = np.zeros(n)
    prm = ffi.new("rc_soft_params *", lib.rc_soft_params_default())
    prm.c = float(c)
    prm.eps = float(eps)
    prm.stiffness = float(stiffness)
    prm.rtol = float(rtol)
    prm.t_max = float(t_max)
    prm.max_steps = int(max_steps)
    prm.shape = SHAPES[shape]
    res = ffi.new("rc_soft_result *")
    check(lib.rc_soft_collide(st, prm, n, ffi.from_buffer("rc_particle[]", b, require_writable=True),
                              ffi.from_buffer("rc_vec3[]", xx, require_writable=True),
                              ffi.from_buffer("double[]", r),
                              ffi.from_buffer("double[]", u, require_writable=True), res),
          "soft_collide")
    return SoftResult(b[:, 0], b[:, 1:1 + d], xx[:, :d], u, res.t_end,
                      np.array([res.normal.x, res.normal.y, res.normal.z][:d]),
                      res.n_contacts, res.n_shape_overlaps, bool(res.finished),
                      res.energy_error, res.momentum_error, res.n_steps, res.n_rhs)
