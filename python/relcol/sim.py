"""The event-driven engine (relcol/sim.h) from Python: a Sim is made from a scenario --
the JSON object relcol-sim reads (apps/sim/SCENARIO.md), as a dict or a file -- and
steps to a time; its state and diagnostics come back as numpy arrays and a dict.

The scenario keys are relcol-sim's: relcol, dim, box, boundary, c, law, restitution,
contact_frame, groups, tc, seed, time, t_end, restart, balls, generate (rack, gas) and outputs
(accepted and ignored: a Sim writes no files). `balls` may also be a dict of arrays,
{"x": (N, dim), "v" or "p": (N, dim), "r": (N,) or scalar, "m": (N,) or scalar (default
r^3), "tau": (N,), "tau_last": (N,) (NaN: no collision yet), "image": (N, dim)}, which is
how one builds a run from numpy. Keyword arguments override keys:
Sim("data/scenarios/rack.json", c=10). A relcol-sim final.json loads with checkpoint=None
(its balls and time; without the checkpoint the continuation re-plans its events, see
rc_sim_sync in relcol/sim.h)."""
import json
import math
import os

import numpy as np

from ._relcol import ffi, lib
from .errors import RelcolError, check
from .kinematics import momentum
from .laws import find_law
from .toi import find_frame

_KEYS = {"relcol", "dim", "box", "boundary", "c", "law", "restitution", "contact_frame", "groups",
         "tc", "seed", "time", "t_end", "restart", "checkpoint", "balls", "generate",
         "outputs"}
_EVENTS = ("ball", "wall", "group", "cell", "stale", "tc")


def _num(value, path, allow_inf=False):
    if allow_inf and value == "inf":
        return math.inf
    if isinstance(value, bool) or not isinstance(value, (int, float, np.floating, np.integer)):
        raise ValueError("%s: must be a number%s, not %r"
                         % (path, ' or "inf"' if allow_inf else "", value))
    value = float(value)
    if not (math.isfinite(value) or (allow_inf and value == math.inf)):
        raise ValueError("%s: must be finite" % path)
    return value


# relcol-sim's range for a ball's numbers (app_check_scale in apps/common/table.c): squares
# and products of magnitudes in [1e-150, 1e150] are finite, normal doubles, so nothing the
# engine forms from them overflows; zero is allowed where the number may be zero.
_SCALE_MIN, _SCALE_MAX = 1e-150, 1e150


def _check_scale(r, m, x, p, source):
    """ValueError naming `source` and the first ball whose radius, rest mass, position or
    momentum lies outside relcol-sim's range, as relcol-sim refuses it."""
    def bad(a, zero_ok):
        a = np.abs(np.asarray(a, dtype=float))
        out = ~((a >= _SCALE_MIN) & (a <= _SCALE_MAX))
        return out & ~(a == 0) if zero_ok else out
    for what, arr, zero_ok in (("radius", r, False), ("rest mass", m, False),
                               ("position", x, True), ("momentum", p, True)):
        hit = bad(arr, zero_ok)
        if hit.ndim > 1:
            hit = hit.any(axis=1)
        if hit.any():
            i = int(np.argmax(hit))
            raise ValueError("%s: gives ball %d a %s out of range: magnitudes must lie in "
                             "[1e-150, 1e150], where their squares and products are finite, "
                             "normal doubles" % (source(i), i, what))


def load_scenario(source):
    """A scenario as a dict: source is a dict (copied), a path to a JSON file or JSON text."""
    if isinstance(source, dict):
        return dict(source)
    if isinstance(source, (str, os.PathLike)) and not str(source).lstrip().startswith("{"):
        with open(source, encoding="utf-8") as f:
            return json.load(f)
    return json.loads(source)


def _rack(s, c, g):
    """relcol-sim's billiard break (apps/sim/scenario.c), in the same arithmetic: 15 balls
    in a triangle whose apex is at 3/4 of the table, a cue ball at 1/4 moving at `speed`."""
    unknown = set(g) - {"kind", "radius", "speed", "aim", "gap"}
    if unknown:
        raise ValueError("generate: unknown key %s" % sorted(unknown)[0])
    if s["dim"] != 2:
        raise ValueError("dim: generate.kind = rack is a 2-D table")
    r = _num(g.get("radius", 0.028575), "generate.radius")
    speed = _num(g.get("speed", 5.0), "generate.speed")
    aim = _num(g.get("aim", 0.0), "generate.aim")
    gap = _num(g.get("gap", 1e-6), "generate.gap")
    if not r > 0:
        raise ValueError("generate.radius: must be > 0")
    if not 0 <= speed < c:
        raise ValueError("generate.speed: must be in [0, c) (c = %g)" % c)
    L, W = s["box"][0], s["box"][1]
    pitch = 2 * r * (1 + gap)
    x0, y0 = 0.75 * L, 0.5 * W
    if x0 + 4 * pitch * math.sqrt(3) / 2 + r > L or 5 * pitch > W or 0.25 * L - r < 0:
        raise ValueError("box: too small for a rack of balls of radius %g" % r)
    x = [[0.25 * L, y0]]
    for row in range(5):
        for j in range(row + 1):
            x.append([x0 + row * pitch * math.sqrt(3) / 2, y0 + (j - row / 2.0) * pitch])
    v = np.zeros((16, 2))
    v[0] = [speed * math.cos(aim), speed * math.sin(aim)]
    m = r * r * r
    return {"x": np.array(x), "p": _momenta(m, v, c), "r": r, "m": m}


def _momenta(m, v, c):
    """Momenta from velocities through the library's rc_momentum_from_velocity, so that a
    scenario gives the same bits here as in relcol-sim."""
    k = ffi.new("double *")
    check(lib.rc_inv_c2(c, k), "c")
    v = np.atleast_2d(v)
    m = np.broadcast_to(np.asarray(m, dtype=float), (len(v),))
    out = np.zeros_like(v)
    p = ffi.new("rc_vec3 *")
    for i, vi in enumerate(v):
        vv = list(vi) + [0.0] * (3 - len(vi))
        rc = lib.rc_momentum_from_velocity(m[i], {"x": vv[0], "y": vv[1], "z": vv[2]}, k[0], p)
        if rc < 0:
            raise RelcolError(rc, "balls[%d].v: |v| = %.17g, c = %g"
                              % (i, float(np.linalg.norm(vi)), c))
        out[i] = [p.x, p.y, p.z][:v.shape[1]]
    return out


class Sim:
    """An event-driven run of hard balls (relcol/sim.h).

    Sim(scenario, **overrides): scenario is a dict, a JSON file's path or JSON text in
    relcol-sim's format (see the module's documentation); overrides replace its keys.

    advance(t) processes every event up to table time t; the state at the engine's time
    is read as arrays: positions, momenta, velocities, rest_masses, radii, proper_times,
    images (periodic wraps); diagnostics() gives the conservation errors and counts.
    """

    def __init__(self, scenario=None, **overrides):
        s = load_scenario(scenario) if scenario is not None else {}
        s.update(overrides)
        unknown = set(s) - _KEYS
        if unknown:
            raise ValueError("%s: unknown key (expected one of: %s)"
                             % (sorted(unknown)[0], ", ".join(sorted(_KEYS))))
        if s.get("relcol", 1) != 1:
            raise ValueError("relcol: unsupported scenario format version %r" % s["relcol"])
        if s.get("checkpoint") is not None:
            raise ValueError("checkpoint: a Sim starts from the balls; delete the key")
        dim = s.get("dim")
        if dim not in (2, 3):
            raise ValueError("dim: required, 2 or 3")
        c = _num(s.get("c", "inf"), "c", allow_inf=True)
        self.scenario = s
        self.dim = dim
        self.c = c
        self.t_end = s.get("t_end")
        d = lib.rc_sim_def_default()
        d.dim = dim
        d.c = c
        d.law = find_law(s.get("law", "zmf"))
        d.frame = find_frame(s.get("contact_frame", "table"))
        rule = s.get("groups", "simultaneous")
        g = lib.rc_group_rule_find(rule.encode() if isinstance(rule, str) else b"")
        if g < 0:
            raise ValueError("groups: unknown rule for simultaneous contacts %r (expected "
                             "simultaneous, sequential, drop)" % (rule,))
        d.groups = g
        rest = s.get("restitution", {})
        d.eps_ball = _num(rest.get("ball", 1.0), "restitution.ball")
        d.eps_wall = _num(rest.get("wall", 1.0), "restitution.wall")
        d.t_c = _num(s.get("tc", 0.0), "tc")
        d.restart = 1 if s.get("restart", False) else 0
        bnd = s.get("boundary", "walls")
        bnd = [bnd] * dim if isinstance(bnd, str) else list(bnd)
        if len(bnd) != dim or any(b not in ("walls", "periodic") for b in bnd):
            raise ValueError('boundary: "walls", "periodic" or a list of %d of them' % dim)
        for k, b in enumerate(bnd):
            d.boundary[k] = lib.RC_SIM_PERIODIC if b == "periodic" else lib.RC_SIM_WALLS
        gen = s.get("generate")
        if (gen is None) == (s.get("balls") is None):
            raise ValueError("balls: give balls or generate (rack or gas), not both")
        if gen is not None and gen.get("kind") == "gas":
            from .gas import gas_init
            if "box" in s:
                raise ValueError("box: must not be given with generate.kind = gas")
            unknown = set(gen) - {"kind", "n", "radius", "packing", "v_rms", "density"}
            if unknown:
                raise ValueError("generate: unknown key %s" % sorted(unknown)[0])
            box, balls = gas_init(dim, int(gen["n"]), gen.get("radius", 1.0), gen["packing"],
                                  gen["v_rms"], c, gen.get("density", 1.0), s.get("seed", 1))
        else:
            box = s.get("box")
            if box is None or len(box) != dim:
                raise ValueError("box: required, %d numbers > 0" % dim)
            box = [_num(v, "box[%d]" % k) for k, v in enumerate(box)]
            if gen is None:
                balls = s["balls"]
            elif gen.get("kind") == "rack":
                s2 = dict(s, box=box)
                balls = _rack(s2, c, gen)
            else:
                raise ValueError("generate.kind: unknown generator %r (expected rack or gas)"
                                 % gen.get("kind"))
        self.box = np.array(box, dtype=float)
        d.box.x, d.box.y = box[0], box[1]
        if dim == 3:
            d.box.z = box[2]
        self._def = ffi.new("rc_sim_def *", d)
        ptr = ffi.new("rc_sim **")
        check(lib.rc_sim_create(self._def, ptr), "Sim")
        self._sim = ffi.gc(ptr[0], lambda q: lib.rc_sim_free(ffi.new("rc_sim **", q)))
        self._balls(balls, c, "generate.radius" if gen is not None else None)
        check(lib.rc_sim_set_time(self._sim, _num(s.get("time", 0.0), "time")), "time")
        self._set(self._cballs)
        self._d0 = self._diag()

    def _balls(self, balls, c, generated=None):
        """rc_sim_ball records from a list of ball objects or a dict of arrays."""
        dim = self.dim
        if isinstance(balls, dict):
            cols = {k: np.asarray(v, dtype=float) for k, v in balls.items()}
            unknown = set(cols) - {"x", "v", "p", "r", "m", "tau", "image", "tau_last"}
            if unknown:
                raise ValueError("balls.%s: unknown key" % sorted(unknown)[0])
            x = np.atleast_2d(cols["x"])
            n = len(x)
            r = np.broadcast_to(cols.get("r", 1.0), (n,))
            m = np.broadcast_to(cols["m"], (n,)) if "m" in cols else r ** 3
            if "v" in cols and "p" in cols:
                raise ValueError("balls: give either v or p, not both")
            if "v" in cols:
                p = _momenta(m, np.atleast_2d(cols["v"]), c)
            else:
                p = np.atleast_2d(cols.get("p", np.zeros((n, dim))))
            tau = np.broadcast_to(cols.get("tau", 0.0), (n,))
            # (TC-model memory: the proper time of each ball's last collision, NaN = none)
            tau_last = np.broadcast_to(cols.get("tau_last", np.nan), (n,))
            image = np.broadcast_to(cols.get("image", np.zeros((n, dim))), (n, dim))
        else:
            n = len(balls)
            x, p, r, m, tau, image = (np.zeros((n, dim)), np.zeros((n, dim)), np.zeros(n),
                                      np.zeros(n), np.zeros(n), np.zeros((n, dim)))
            tau_last = np.full(n, np.nan)
            for i, b in enumerate(balls):
                unknown = set(b) - {"x", "v", "p", "r", "m", "tau", "image", "tau_last"}
                if unknown:
                    raise ValueError("balls[%d].%s: unknown key" % (i, sorted(unknown)[0]))
                r[i] = _num(b.get("r", float("nan")), "balls[%d].r" % i)
                m[i] = _num(b["m"], "balls[%d].m" % i) if "m" in b else r[i] ** 3
                x[i] = b["x"]
                tau[i] = b.get("tau", 0.0)
                if "tau_last" in b:
                    tau_last[i] = _num(b["tau_last"], "balls[%d].tau_last" % i)
                image[i] = b.get("image", [0] * dim)
                if "v" in b and "p" in b:
                    raise ValueError("balls[%d]: give either v or p, not both" % i)
                if "v" in b:
                    p[i] = _momenta(m[i], np.array([b["v"]], dtype=float), c)[0]
                elif "p" in b:
                    p[i] = b["p"]
        if x.shape != (n, dim) or p.shape != (n, dim):
            raise ValueError("balls: x and v (or p) must be (N, %d) arrays" % dim)
        if np.any(m <= 0):
            raise RelcolError(-3, "balls", int(np.argmax(m <= 0)))
        _check_scale(r, m, x, p, (lambda i: generated) if generated else
                     (lambda i: "balls[%d]" % i))
        cb = ffi.new("rc_sim_ball[]", n)
        for i in range(n):
            bi = cb[i]
            bi.x.x, bi.x.y = x[i, 0], x[i, 1]
            bi.p.x, bi.p.y = p[i, 0], p[i, 1]
            if dim == 3:
                bi.x.z, bi.p.z = x[i, 2], p[i, 2]
            bi.r, bi.m, bi.tau = r[i], m[i], tau[i]
            if not math.isnan(tau_last[i]):
                bi.collided, bi.tau_last = 1, tau_last[i]
            for k in range(dim):
                bi.image[k] = int(image[i, k])
        self._cballs = cb
        self.n = n

    def _set(self, cb):
        bad = ffi.new("size_t *")
        rc = lib.rc_sim_set_balls(self._sim, len(cb), cb, bad)
        check(rc, "balls", int(bad[0]))

    def advance(self, t, max_events=0):
        """Process events up to table time t (or max_events of them, 0 = all); returns
        self. A failing law or a stalled run raises RelcolError (the state stays whole)."""
        check(lib.rc_sim_advance(self._sim, float(t), int(max_events)), "advance to t = %g" % t)
        return self

    def run(self):
        """advance() to the scenario's t_end."""
        if self.t_end is None:
            raise ValueError("t_end: the scenario has none; call advance(t)")
        return self.advance(_num(self.t_end, "t_end"))

    @property
    def time(self):
        """The engine's table time."""
        return lib.rc_sim_time(self._sim)

    def _read(self, latest=False, slice_id=None):
        n, dim = lib.rc_sim_count(self._sim), self.dim
        out = ffi.new("rc_sim_ball *")
        x, p = np.empty((n, dim)), np.empty((n, dim))
        r, m, tau = np.empty(n), np.empty(n), np.empty(n)
        image = np.empty((n, dim), dtype=np.int64)
        ahead = np.zeros(n, dtype=np.int64)
        if slice_id is not None:
            latest = True  # (no kink_ahead: a final slice has none to flag)
            get = lambda sim, i, o: lib.rc_sim_slice_get(sim, slice_id, i, o)
        else:
            get = lib.rc_sim_get_ball_latest if latest else lib.rc_sim_get_ball
        for i in range(n):
            check(get(self._sim, i, out), "ball", i)
            x[i] = (out.x.x, out.x.y, out.x.z)[:dim]
            p[i] = (out.p.x, out.p.y, out.p.z)[:dim]
            r[i], m[i], tau[i] = out.r, out.m, out.tau
            image[i] = list(out.image)[:dim]
            if not latest:
                ahead[i] = lib.rc_sim_kink_ahead(self._sim, i)
        return x, p, r, m, tau, image, ahead

    def state(self, latest=False):
        """Every ball at the engine's time, as a dict of arrays: x, p, v, r, m (rest
        mass), tau (proper time), image (periodic wraps), kink_ahead, t. In the covariant
        frame a ball's kink may lie after the engine's time: the state is then the one it
        has there, on its incoming line, and kink_ahead is 1 (2: not recorded, see
        rc_sim_kink_ahead in relcol/sim.h); latest=True reads every ball's latest segment
        instead (each change at its contact event's table time, as the other frames do;
        rc_sim_get_ball_latest), whose sums are the conserved ones."""
        x, p, r, m, tau, image, ahead = self._read(latest)
        mr = np.sqrt(m * m + np.sum(p * p, axis=1) * (0.0 if math.isinf(self.c) else self.c ** -2))
        return {"t": self.time, "x": x, "p": p, "v": p / mr[:, None], "r": r, "m": m,
                "tau": tau, "image": image, "kink_ahead": ahead}

    def slice_request(self, t):
        """Ask for the delayed table-time slice at t >= the engine's time (relcol/sim.h,
        rc_sim_slice_request): every ball's state at t on its worldline, kept by the engine
        as later collisions place or undo kinks before t. Returns its id."""
        sid = ffi.new("uint32_t *")
        check(lib.rc_sim_slice_request(self._sim, _num(t, "t"), sid), "slice at t = %g" % t)
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
        x, p, r, m, tau, image, _ = self._read(slice_id=int(sid))
        if release:
            self.slice_release(sid)
        mr = np.sqrt(m * m + np.sum(p * p, axis=1) * (0.0 if math.isinf(self.c) else self.c ** -2))
        return {"t": ts, "x": x, "p": p, "v": p / mr[:, None], "r": r, "m": m,
                "tau": tau, "image": image}

    def slice_release(self, sid):
        """Drop slice sid."""
        check(lib.rc_sim_slice_release(self._sim, int(sid)), "slice %d" % sid)

    positions = property(lambda self: self._read()[0], doc="centres, (N, dim)")
    momenta = property(lambda self: self._read()[1], doc="momenta, (N, dim)")
    radii = property(lambda self: self._read()[2], doc="rest radii, (N,)")
    rest_masses = property(lambda self: self._read()[3], doc="rest masses, (N,)")
    proper_times = property(lambda self: self._read()[4], doc="proper times, (N,)")
    images = property(lambda self: self._read()[5], doc="periodic wraps, (N, dim)")
    velocities = property(lambda self: self.state()["v"], doc="velocities p / M, (N, dim)")

    def _diag(self):
        d = ffi.new("rc_sim_diag *")
        check(lib.rc_sim_diagnostics(self._sim, d), "diagnostics")
        return d

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
