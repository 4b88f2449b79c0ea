"""Gases: the engine's equilibrium start (rc_sim_gas_init) and the exact 1-D gas of
point particles (relcol/gas1d.h), whose momenta relax to the Juttner distribution."""
import math

import numpy as np

from ._relcol import ffi, lib
from .errors import RelcolError, check, shape_error
from .laws import find_law


def _scalar(func, name, v):
    """v as a float; ValueError naming the argument if it is not one number."""
    a = np.asarray(v, dtype=float)
    if a.ndim != 0:
        raise shape_error(func, name, a.shape, "a number")
    return float(a)


def gas_init(dim, n, radius, packing, v_rms, c=math.inf, density=1.0, seed=1):
    """n equal balls on random lattice sites of a square / cubic box sized for the packing
    fraction, isotropic random momenta of rms speed v_rms (< c), zero total momentum:
    relcol-sim's generator {"kind": "gas"} (rc_sim_gas_init), read by its scenario reader,
    whose rules and messages it keeps ("gas_init: generate.n: must be a whole number in
    [1, 1e8]"). Returns (box, balls) with balls a dict of arrays {"x", "p", "r", "m"}."""
    from .scenario import Scenario
    sc = Scenario({"dim": dim, "c": c, "seed": seed, "t_end": 1.0,
                   "generate": {"kind": "gas", "n": n, "radius": radius, "packing": packing,
                                "v_rms": v_rms, "density": density}}, name="gas_init")
    p = sc.ptr
    return [p.box.x, p.box.y, p.box.z][:int(p.dim)], sc.balls()


def _column(func, name, a, n):
    """a as a contiguous (n,) float column (a scalar broadcasts); ValueError naming the
    argument otherwise."""
    a = np.asarray(a, dtype=float)
    if a.ndim == 0:
        a = np.broadcast_to(a, (n,))
    if a.shape != (n,):
        raise shape_error(func, name, a.shape, "(%d,) like x, or a scalar" % n
                          if name != "x" else "(N,)")
    return np.ascontiguousarray(a)


class Gas1D:
    """N point particles on [0, length] between reflecting walls, elastic collisions of
    the law `law` (default zmf), any c; exact event-driven (relcol/gas1d.h).
    x: positions, strictly increasing in [0, length]; m: rest masses; p: momenta."""

    def __init__(self, x, m, p, length=1.0, c=math.inf, t0=0.0, law="zmf"):
        x = np.asarray(x, dtype=float)
        if x.ndim != 1 or len(x) == 0:
            raise shape_error("Gas1D", "x", x.shape, "(N,) with N >= 1")
        n = len(x)
        self._x = _column("Gas1D", "x", x, n)
        self._m = _column("Gas1D", "m", m, n)
        self._p = _column("Gas1D", "p", p, n)
        length, c, t0 = (_scalar("Gas1D", k, v) for k, v in
                         (("length", length), ("c", c), ("t0", t0)))
        d = ffi.new("rc_gas1d_def *", lib.rc_gas1d_def_default())
        d.n, d.length, d.c, d.t0 = n, float(length), float(c), float(t0)
        d.x = ffi.from_buffer("double[]", self._x)
        d.m = ffi.from_buffer("double[]", self._m)
        d.p = ffi.from_buffer("double[]", self._p)
        d.law = find_law(law)
        out = ffi.new("rc_gas1d **")
        bad = ffi.new("size_t *")
        rc = lib.rc_gas1d_create(d, out, bad)
        if rc < 0:
            raise RelcolError(rc, "Gas1D", int(bad[0]), self._field(rc, int(bad[0]), length, c, t0))
        self._g = ffi.gc(out[0], lambda q: lib.rc_gas1d_free(ffi.new("rc_gas1d **", q)))
        self.n = n

    def _field(self, rc, i, length, c, t0):
        """The argument the library's code rc points at (the library says what is wrong,
        and *bad which particle; this says which array)."""
        if rc == -6:  # RC_ESPEEDOFLIGHT
            return "c"
        if rc == -3:  # RC_EMASS
            return "m[%d]" % i
        if rc == -2:  # RC_ENONFINITE: the first non-finite input
            for k, v in (("length", length), ("t0", t0)):
                if not math.isfinite(v):
                    return k
            for k, a in (("x", self._x), ("m", self._m), ("p", self._p)):
                bad = ~np.isfinite(a)
                if bad.any():
                    return "%s[%d]" % (k, int(np.argmax(bad)))
        if rc == -1:  # RC_EINVAL: the box, or the positions' order and range
            if not length > 0:
                return "length"
            return "x[%d]" % i
        return None

    def advance(self, t, max_events=0):
        """Process events up to time t (or max_events of them); returns self."""
        check(lib.rc_gas1d_advance(self._g, float(t), int(max_events)), "advance")
        return self

    @property
    def time(self):
        return lib.rc_gas1d_time(self._g)

    _KINDS = ("pair", "wall_left", "wall_right")

    def step(self, t_end=math.inf):
        """Process the next event if it happens by t_end and return it as a dict {"t", "x",
        "kind" ("pair": particles i and i + 1; "wall_left", "wall_right": particle i), "i"};
        otherwise move the gas's time to t_end and return None."""
        ev = ffi.new("rc_gas1d_event *")
        rc = lib.rc_gas1d_step(self._g, float(t_end), ev)
        if rc == lib.RC_MISS:
            return None
        check(rc, "step")
        return {"t": ev.t, "x": ev.x, "kind": self._KINDS[ev.kind], "i": int(ev.i)}

    def segment(self, i):
        """Particle i's worldline since its last event: {"t", "x"} of that event (or the
        start), and "m", "p", "v" on the straight line x + v (t' - t) until its next one.
        Read after each step() for the particles the event names, these rebuild every
        worldline exactly."""
        s = ffi.new("rc_gas1d_segment *")
        check(lib.rc_gas1d_segment_get(self._g, int(i), s), "segment", int(i))
        return {"t": s.t, "x": s.x, "m": s.m, "p": s.p, "v": s.v}

    def state(self):
        """(x, m, p) arrays, left to right, at the gas's time."""
        x, m, p = np.empty(self.n), np.empty(self.n), np.empty(self.n)
        check(lib.rc_gas1d_get(self._g, ffi.from_buffer("double[]", x, require_writable=True),
                               ffi.from_buffer("double[]", m, require_writable=True),
                               ffi.from_buffer("double[]", p, require_writable=True)), "state")
        return x, m, p

    def stats(self):
        """Event counts and the walls' impulses."""
        s = ffi.new("rc_gas1d_stats *")
        check(lib.rc_gas1d_stats_get(self._g, s), "stats")
        return {"pair_events": int(s.pair_events), "wall_events": [int(s.wall_events[0]),
                int(s.wall_events[1])], "declined": int(s.declined),
                "wall_impulse": [s.wall_impulse[0], s.wall_impulse[1]]}
