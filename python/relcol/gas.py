"""Gases: the engine's equilibrium start (rc_sim_gas_init) and the exact 1-D gas of
point particles (relcol/gas1d.h), whose momenta relax to the Juttner distribution."""
import math

import numpy as np

from ._relcol import ffi, lib
from .errors import check
from .laws import find_law


def gas_init(dim, n, radius, packing, v_rms, c=math.inf, density=1.0, seed=1):
    """n equal balls on random lattice sites of a square / cubic box sized for the packing
    fraction, isotropic random momenta of rms speed v_rms (< c), zero total momentum.
    Returns (box, balls) with balls a dict of arrays {"x", "p", "r", "m"} for Sim."""
    g = ffi.new("rc_sim_gas_def *")
    g.dim, g.n, g.radius, g.packing = int(dim), int(n), float(radius), float(packing)
    g.v_rms, g.c, g.density, g.seed = float(v_rms), float(c), float(density), int(seed)
    box = ffi.new("rc_vec3 *")
    cb = ffi.new("rc_sim_ball[]", int(n))
    check(lib.rc_sim_gas_init(g, box, cb), "gas_init")
    x = np.array([[b.x.x, b.x.y, b.x.z][:dim] for b in cb])
    p = np.array([[b.p.x, b.p.y, b.p.z][:dim] for b in cb])
    return [box.x, box.y, box.z][:dim], {"x": x, "p": p, "r": np.array([b.r for b in cb]),
                                         "m": np.array([b.m for b in cb])}


class Gas1D:
    """N point particles on [0, length] between reflecting walls, elastic collisions of
    the law `law` (default zmf), any c; exact event-driven (relcol/gas1d.h).
    x: positions, strictly increasing in [0, length]; m: rest masses; p: momenta."""

    def __init__(self, x, m, p, length=1.0, c=math.inf, t0=0.0, law="zmf"):
        self._x = np.ascontiguousarray(x, dtype=float)
        n = len(self._x)
        self._m = np.ascontiguousarray(np.broadcast_to(np.asarray(m, dtype=float), (n,)))
        self._p = np.ascontiguousarray(p, dtype=float)
        d = ffi.new("rc_gas1d_def *", lib.rc_gas1d_def_default())
        d.n, d.length, d.c, d.t0 = n, float(length), float(c), float(t0)
        d.x = ffi.from_buffer("double[]", self._x)
        d.m = ffi.from_buffer("double[]", self._m)
        d.p = ffi.from_buffer("double[]", self._p)
        d.law = find_law(law)
        out = ffi.new("rc_gas1d **")
        bad = ffi.new("size_t *")
        rc = lib.rc_gas1d_create(d, out, bad)
        check(rc, "Gas1D", int(bad[0]))
        self._g = ffi.gc(out[0], lambda q: lib.rc_gas1d_free(ffi.new("rc_gas1d **", q)))
        self.n = n

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
