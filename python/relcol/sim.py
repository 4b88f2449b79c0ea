"""The event-driven engine (relcol/sim.h) from Python: a Sim is made from a scenario --
the JSON object relcol-sim reads (apps/sim/SCENARIO.md), as a dict, a file or JSON text,
read by relcol-sim's own reader (relcol.scenario) -- and steps to a time; its state comes
back as numpy arrays filled in C in one call, its diagnostics as a dict.

`balls` may also be a dict of arrays, {"x": (N, dim), "v" or "p": (N, dim), "r": (N,) or
scalar, "m": (N,) or scalar (default r^3), "tau": (N,), "tau_last": (N,) (NaN: no
collision yet), "image": (N, dim)}, which is how one builds a run from numpy. Keyword
arguments override keys: Sim("data/scenarios/rack.json", c=10). t_end is optional (a Sim
without one runs as far as asked). A relcol-sim final.json loads with its checkpoint and
continues bit for bit as relcol-sim would; checkpoint=None starts afresh from its balls
(the events are then planned again, see rc_sim_sync in relcol/sim.h)."""
import math
import os

import numpy as np

from ._relcol import ffi, lib
from .errors import check
from .kinematics import inv_c2 as _inv_c2
from .scenario import ScenarioError, load_scenario, parse

_EVENTS = ("ball", "wall", "group", "cell", "stale", "tc")
_FIELDS = ("x", "p", "v", "r", "m", "tau", "tau_last", "image", "ahead")


class Sim:
    """An event-driven run of hard balls (relcol/sim.h).

    Sim(scenario, **overrides): scenario is a dict, a JSON file's path or JSON text in
    relcol-sim's format (see the module's documentation); overrides replace its keys.

    integrate(t) (or advance(t)) processes every event up to table time t; steps(dt) and
    events() iterate over a run; the state at the engine's time is read as arrays:
    positions, momenta, velocities, rest_masses, radii, proper_times, images, or all at
    once with state(); diagnostics() gives the conservation errors and counts; add()
    puts balls in, set_c() changes the speed of light, save() writes the run as
    relcol-sim's final.json does (scenario + checkpoint) and Sim(path) continues it.
    """

    def __init__(self, scenario=None, **overrides):
        self._scn = parse(scenario, overrides)
        self.scenario = self._scn.dict
        p = self._scn.ptr
        self.dim = int(p.dim)
        self.c = float(p.c)
        self.t_end = self._scn.t_end
        self.box = np.array([p.box.x, p.box.y, p.box.z][:self.dim])
        self._def = ffi.new("rc_sim_def *", lib.scn_sim_def(p))
        if self._scn.field_axis is not None:
            self._def.g_axis = self._scn.field_axis
        ptr = ffi.new("rc_sim **")
        check(lib.rc_sim_create(self._def, ptr), "Sim")
        self._sim = ffi.gc(ptr[0], lambda q: lib.rc_sim_free(ffi.new("rc_sim **", q)))
        err = ffi.new("char[]", lib.APP_ERR_LEN)
        if lib.scn_start(self._sim, p, self._scn.file.encode(), err) != 0:
            raise ScenarioError(ffi.string(err).decode())
        self.t0 = self.time
        self._d0 = self._diag()
        self._h0 = self._field_total() if self.gravity else None

    @property
    def gravity(self):
        """The field as {"g", "coupling", "axis"} (the axis it points against), or None."""
        d = self._def
        if d.gravity == ffi.NULL:
            return None
        return {"g": float(d.g), "coupling": ffi.string(d.gravity.name).decode(),
                "axis": self.dim - 1 if d.g_axis < 0 else int(d.g_axis)}

    def _field_total(self):
        h, booked = self.field_energy()
        return h - booked, abs(h) if h != 0 else 1.0

    def profile(self, slabs=20):
        """The gas's profile along the field's axis now (the last axis without a field), in
        `slabs` slabs of the box's height: a structured numpy array with relcol-sim's
        profiles.csv columns (relcol.field), from one read of every ball's x, p, v."""
        from .field import profile
        grav = self.gravity or {"g": 0.0, "coupling": None, "axis": self.dim - 1}
        st = self._read(("x", "p", "v"))
        return profile(st, self.box[grav["axis"]], grav["g"], self.c, grav["coupling"],
                       grav["axis"], slabs, self.box)

    @classmethod
    def load(cls, path, **overrides):
        """A run saved by save() or relcol-sim's final.json, continued bit for bit."""
        return cls(os.fspath(path), **overrides)

    @property
    def n(self):
        """The number of balls."""
        return int(lib.rc_sim_count(self._sim))

    # ---- stepping ---------------------------------------------------------------------

    def advance(self, t, max_events=0):
        """Process events up to table time t (or max_events of them, 0 = all); returns
        self. A failing law or a stalled run raises RelcolError (the state stays whole)."""
        check(lib.rc_sim_advance(self._sim, float(t), int(max_events)), "advance to t = %g" % t)
        return self

    def integrate(self, t, every=None, callback=None):
        """Advance to table time t (REBOUND's word); with callback, call callback(self)
        every `every` time units from the current time (the last call at t), or after
        every event when every="event". Returns self."""
        if callback is None:
            return self.advance(t)
        it = self.events(t) if every == "event" else self.steps(every, t)
        for _ in it:
            callback(self)
        return self

    def steps(self, dt, t_end=None):
        """Iterate over the run at times t0 + k dt up to t_end (default the scenario's
        t_end), advancing the engine to each and yielding the Sim there; the grid is
        counted in whole steps from the current time, so it does not drift."""
        dt = float(dt)
        if not (dt > 0 and math.isfinite(dt)):
            raise ValueError("steps: dt must be a finite number > 0, not %r" % dt)
        end = self._end(t_end)
        t0, k = self.time, 1
        while True:
            t = min(t0 + k * dt, end)
            self.advance(t)
            yield self
            if t >= end:
                return
            k += 1

    def events(self, t_end=None):
        """Iterate over the run event by event up to t_end (default the scenario's
        t_end), yielding the Sim at each event's table time (cell crossings and stale
        queue entries included: see diagnostics()["events"]); the last yield is at
        t_end."""
        end = self._end(t_end)
        while self.time < end:
            self.advance(end, max_events=1)
            yield self

    def _end(self, t_end):
        end = self.t_end if t_end is None else float(t_end)
        if end is None:
            raise ValueError("t_end: the scenario has none; give t_end")
        return end

    def run(self):
        """advance() to the scenario's t_end."""
        return self.advance(self._end(None))

    def set_c(self, c):
        """Change the speed of light of the running engine (rc_sim_set_c in relcol/sim.h:
        every ball keeps its momentum and rest mass; c = inf is classical). Returns
        self."""
        c = float(c)
        check(lib.rc_sim_set_c(self._sim, c), "set_c(%r)" % c)
        self.c = c
        self._def.c = c
        self._scn.ptr.c = c
        if self._h0:  # (the field's H is a function of c: its reference is taken anew)
            self._h0 = self._field_total()
        return self

    def add(self, balls=None, **ball):
        """Add balls: a list of ball objects or a dict of arrays as in a scenario, or one
        ball as keywords (x=, v= or p=, r=, m=, ...). They are read by the scenario reader
        (same rules, same messages) and given with the balls already there to
        rc_sim_set_balls, which plans the events afresh (a checkpoint's schedule is not
        kept) and refuses overlaps (the run then stays as it was); the diagnostics
        restart from the new total. Returns self."""
        if balls is None:
            balls = [ball]
        elif ball:
            raise ValueError("add: give balls or one ball's keywords, not both")
        head = {k: v for k, v in self.scenario.items()
                if k in ("relcol", "dim", "box", "boundary", "c", "law", "contact_frame")}
        head.update(c=self.c, time=self.time, balls=balls)
        if "box" not in head:
            head["box"] = self.box
        new = parse(head, name="add").ptr
        n, k = self.n, int(new.n)
        all_balls = ffi.new("rc_sim_ball[]", n + k)
        bad = ffi.new("size_t *")
        check(lib.rcpy_sim_balls(self._sim, n, all_balls, bad), "ball", int(bad[0]))
        ffi.memmove(all_balls + n, new.balls, k * ffi.sizeof("rc_sim_ball"))
        before = self.checkpoint()  # (a refused add leaves the run as it was, exactly)
        rc = lib.rc_sim_set_balls(self._sim, n + k, all_balls, bad)
        if rc < 0:
            self.restore(before)
            i = int(bad[0])
            raise ScenarioError("add: balls[%d]: %s" % (i - n, "overlaps another ball"
                                if rc == lib.RC_EOVERLAP else "the ball's shape is not inside "
                                "the box" if rc == -1 else ffi.string(lib.rc_strerror(rc)).decode()))
        self._d0 = self._diag()
        return self

    # ---- checkpoints ------------------------------------------------------------------

    def save(self, path, t_end=None):
        """Write the run as relcol-sim writes final.json: path (NAME.json) is the
        scenario with the balls and time now, "restart": true, naming NAME.ckpt beside it,
        the engine's whole state; Sim(path) (or relcol-sim path) continues it bit for bit.
        t_end: the end written (default the scenario's, or as long again as run so far).
        Both files are written atomically. Returns path."""
        path = os.fspath(path)
        grav = self.gravity
        if grav and grav["axis"] != self.dim - 1:
            raise ValueError("save: the field is along axis %d, and relcol-sim's scenario has "
                             "it along the last axis only (gravity.axis)" % grav["axis"])
        folder, base = os.path.split(os.path.abspath(path))
        if not base.endswith(".json") or len(base) <= 5:
            raise ValueError("save: %r: the file name must end in .json" % path)
        if t_end is None:
            t_end = self.t_end if self.t_end is not None and self.t_end > self.time else \
                self.time + max(self.time - self.t0, 1.0)
        err = ffi.new("char[]", lib.APP_ERR_LEN)
        if lib.scn_save(folder.encode(), base[:-5].encode(), self._scn.ptr, self._sim,
                        float(t_end), err) != 0:
            raise OSError("save: %s" % ffi.string(err).decode())
        return path

    def checkpoint(self):
        """The engine's whole state as bytes (rc_sim_checkpoint_write)."""
        size = ffi.new("size_t *")
        check(lib.rc_sim_checkpoint_size(self._sim, size), "checkpoint")
        buf = bytearray(size[0])
        check(lib.rc_sim_checkpoint_write(self._sim, ffi.from_buffer(buf), size[0]),
              "checkpoint")
        return bytes(buf)

    def restore(self, data):
        """Replace the state by checkpoint bytes from a Sim of an equal definition
        (rc_sim_checkpoint_read: damaged or foreign bytes are refused). Returns self."""
        check(lib.rc_sim_checkpoint_read(self._sim, ffi.from_buffer(data), len(data)),
              "restore")
        return self

    # ---- state ------------------------------------------------------------------------

    @property
    def time(self):
        """The engine's table time."""
        return lib.rc_sim_time(self._sim)

    def _read(self, fields, which=0, slice_id=0):
        """The named fields of every ball, filled by rcpy_sim_read in one call."""
        n, dim = self.n, self.dim
        shapes = {"x": (n, dim), "p": (n, dim), "v": (n, dim), "image": (n, dim)}
        types = {"image": np.int32, "ahead": np.int8}
        out, ptrs = {}, []
        for f in _FIELDS:
            if f in fields:
                a = np.empty(shapes.get(f, (n,)), dtype=types.get(f, np.float64))
                out[f] = a
                ctype = {"image": "int32_t[]", "ahead": "int8_t[]"}.get(f, "double[]")
                ptrs.append(ffi.from_buffer(ctype, a, require_writable=True))
            else:
                ptrs.append(ffi.NULL)
        bad = ffi.new("size_t *")
        inv_c2 = _inv_c2(self.c)
        check(lib.rcpy_sim_read(self._sim, which, slice_id, n, dim, inv_c2, *ptrs, bad),
              "ball", int(bad[0]))
        return out

    def state(self, latest=False):
        """Every ball at the engine's time, as a dict of arrays: x, p, v, r, m (rest
        mass), tau (proper time), tau_last (TC memory, NaN: none), image (periodic
        wraps), kink_ahead, t. In the covariant frame a ball's kink may lie after the
        engine's time: the state is then the one it has there, on its incoming line, and
        kink_ahead is 1 (2: not recorded, see rc_sim_kink_ahead in relcol/sim.h);
        latest=True reads every ball's latest segment instead (each change at its contact
        event's table time, as the other frames do; rc_sim_get_ball_latest), whose sums
        are the conserved ones."""
        # (only a per_ball frame at finite c has kinks ahead: elsewhere they are all 0)
        kinks = not latest and self._def.frame.per_ball and not math.isinf(self.c)
        st = self._read(_FIELDS if kinks else _FIELDS[:-1], 1 if latest else 0)
        st["kink_ahead"] = st.pop("ahead", np.zeros(self.n, dtype=np.int8))
        st["t"] = self.time
        return st

    def slice_request(self, t):
        """Ask for the delayed table-time slice at t >= the engine's time (relcol/sim.h,
        rc_sim_slice_request): every ball's state at t on its worldline, kept by the engine
        as later collisions place or undo kinks before t. Returns its id."""
        sid = ffi.new("uint32_t *")
        check(lib.rc_sim_slice_request(self._sim, float(t), sid),
              "slice at t = %g (not in a scenario with \"gravity\")" % t)
        return int(sid[0])

    def slice_ready(self, sid):
        """A dict: final (bool), ts, t_final (the engine time from which it is final, as
        now bounded), late (changes after it was first read: relcol/sim.h), reach (the
        largest engine time minus ts at which the slice changed, -inf: none)."""
        info = ffi.new("rc_sim_slice_info *")
        rc = lib.rc_sim_slice_ready(self._sim, int(sid), info)
        check(rc, "slice %d" % sid)
        return {"final": rc == 1, "ts": info.ts, "t_final": info.t_final,
                "late": int(info.late), "reach": info.reach}

    def slice_state(self, sid, release=False):
        """Slice sid's balls as a dict like state() (t: the slice's time), once final
        (RelcolError RC_ENOTREADY before: advance to slice_ready(sid)["t_final"]). Its sums
        are not the conserved ones (relcol/sim.h). release=True drops it after reading."""
        ts = self.slice_ready(sid)["ts"]
        st = self._read(_FIELDS[:-1], lib.RCPY_SLICE, int(sid))
        if release:
            self.slice_release(sid)
        st["t"] = ts
        return st

    def slice_release(self, sid):
        """Drop slice sid."""
        check(lib.rc_sim_slice_release(self._sim, int(sid)), "slice %d" % sid)

    @property
    def positions(self):
        """centres, (N, dim): the library's lean read (rc_sim_get_positions), state()'s x
        bit for bit"""
        x = np.empty((self.n, self.dim))
        check(lib.rc_sim_get_positions(self._sim, x.shape[0], x.shape[1],
                                       ffi.from_buffer("double[]", x, require_writable=True), 0),
              "positions")
        return x

    momenta = property(lambda self: self._read(("p",))["p"], doc="momenta, (N, dim)")
    radii = property(lambda self: self._read(("r",))["r"], doc="rest radii, (N,)")
    rest_masses = property(lambda self: self._read(("m",))["m"], doc="rest masses, (N,)")
    proper_times = property(lambda self: self._read(("tau",))["tau"], doc="proper times, (N,)")
    images = property(lambda self: self._read(("image",))["image"], doc="periodic wraps, (N, dim)")
    velocities = property(lambda self: self._read(("v",))["v"],
                          doc="velocities p / M (rc_velocity), (N, dim)")

    def _diag(self):
        d = ffi.new("rc_sim_diag *")
        check(lib.rc_sim_diagnostics(self._sim, d), "diagnostics")
        return d

    def field_energy(self):
        """With a uniform field ("gravity"): (h, booked), the sum of the coupling's conserved
        energies and the change booked at contacts (rc_sim_field_energy, papers/gravity.md
        section 4); h - booked stays constant. RelcolError (RC_EINVAL) without a field."""
        h, w = ffi.new("double *"), ffi.new("double *")
        check(lib.rc_sim_field_energy(self._sim, h, w), "field_energy (a scenario with \"gravity\")")
        return float(h[0]), float(w[0])

    def diagnostics(self):
        """Conservation and counts since the Sim was made, as relcol-sim's summary.json
        words them: energy_error (relative to the starting energy, kinetic + heat),
        momentum_error (|change of ball momentum + wall impulse| / sum |p|), collisions
        (contacts resolved) and events by kind, overlaps (contacts the overlap policy
        decided) by kind, heat, rest_mass_total, energy, kinetic_energy, momentum,
        wall_impulse, max_group, group_fallbacks, group_sequential, time, and for the
        covariant frame tube_conflicts, order_conflicts and rollbacks (relcol/sim.h); and
        "model", the validity report as summary.json's model block words it (the whole
        run: relcol/validity.h)."""
        d, d0 = self._diag(), self._d0
        de = d.energy - d0.energy
        dp = np.array([d.momentum.x + d.wall_impulse.x - d0.momentum.x - d0.wall_impulse.x,
                       d.momentum.y + d.wall_impulse.y - d0.momentum.y - d0.wall_impulse.y,
                       d.momentum.z + d.wall_impulse.z - d0.momentum.z - d0.wall_impulse.z])
        ps = max(d.momentum_scale, d0.momentum_scale)
        return {
            "time": d.time,
            "energy_error": de / d0.energy if d0.energy > 0 else de,
            "momentum_error": float(np.linalg.norm(dp) / ps) if ps > 0 else 0.0,
            "collisions": int(d.collisions - d0.collisions),
            "events": {k: int(d.events[i] - d0.events[i]) for i, k in enumerate(_EVENTS)},
            "overlaps": int(d.overlaps - d0.overlaps),
            "overlaps_by_kind": {k: int(d.overlaps_by_kind[i] - d0.overlaps_by_kind[i])
                                 for i, k in enumerate(("ball", "wall", "group"))},
            "max_overlap": d.max_overlap,
            "heat": d.heat - d0.heat,
            "energy": d.energy,
            "kinetic_energy": d.kinetic,
            "rest_mass_total": d.rest_mass,
            "mass_rel_total": d.mass_rel,
            "momentum": np.array([d.momentum.x, d.momentum.y, d.momentum.z])[:self.dim],
            "wall_impulse": np.array([d.wall_impulse.x, d.wall_impulse.y,
                                      d.wall_impulse.z])[:self.dim],
            "max_group": int(d.max_group),
            "group_fallbacks": int(d.group_fallbacks - d0.group_fallbacks),
            "group_sequential": int(d.group_sequential - d0.group_sequential),
            "tube_conflicts": int(d.tube_conflicts - d0.tube_conflicts),
            "order_conflicts": int(d.order_conflicts - d0.order_conflicts),
            "rollbacks": int(d.rollbacks - d0.rollbacks),
            "model": self._model(),
            # (a field: the relative change of its conserved H minus what contacts booked)
            **({"field_energy_error": (self._field_total()[0] - self._h0[0]) / self._h0[1]}
               if self._h0 else {}),
        }

    def _model(self):
        v = ffi.new("rc_validity *")
        check(lib.rc_sim_validity(self._sim, v), "validity")
        return {
            "verdict": ffi.string(v.verdict_name).decode(),
            "threshold_p_model": v.threshold, "covariant": bool(v.covariant),
            "p_model": v.p_model, "p_all": v.p_all, "largest_cluster": v.largest_model,
            "largest_cluster_all": v.largest_all, "nu_r_c": v.nu_r_c,
            "policy_share": v.policy_share, "policy": int(v.policy),
            "collisions": int(v.collisions), "tube_conflicts": int(v.tube_conflicts),
            "order_conflicts": int(v.order_conflicts), "undone": int(v.undone),
            "kink_events": int(v.kink_events), "kink_pairs": int(v.kink_pairs),
            "kink_pairs_model": int(v.kink_pairs_model), "crossing": int(v.crossing),
            "crossing_model": int(v.crossing_model),
        }

    def hash(self):
        """FNV-1a hash of every ball's state bits (rc_sim_hash): equal runs, equal hashes."""
        return int(lib.rc_sim_hash(self._sim))

    def __repr__(self):
        return "<relcol.Sim %d-D, %d balls, c = %g, t = %g>" % (self.dim, self.n, self.c, self.time)


__all__ = ["Sim", "load_scenario", "ScenarioError"]
