"""Scenarios through relcol-sim's own reader (apps/sim/scenario.c, linked into the
compiled module): a dict, a JSON file or JSON text is handed to the C reader whole, so
that every rule -- keys, ranges, |v| < c, the rack and gas generators, balls inside the
box -- is the one relcol-sim applies, and an error is its message, naming the JSON path
("balls[0].r: radius must be > 0"). Python only turns numpy arrays into JSON (floats in
round-trip form) and checks that the arrays of a dict of balls have matching lengths."""
import json
import math
import os
import sys

import numpy as np

from ._relcol import ffi, lib
from .errors import ScenarioError


def load_scenario(source):
    """A scenario as a dict: source is a dict (copied), a path to a JSON file or JSON text."""
    if isinstance(source, dict):
        return dict(source)
    if isinstance(source, (str, os.PathLike)) and not str(source).lstrip().startswith("{"):
        with open(source, encoding="utf-8") as f:
            return json.load(f)
    return json.loads(source)


def _plain(v):
    """v as JSON the C reader takes: arrays as lists, a non-finite number as a string
    (JSON has none: the reader then names the key, "must be a number")."""
    if isinstance(v, dict):
        return {k: _plain(x) for k, x in v.items()}
    if isinstance(v, np.ndarray):
        return _plain(v.tolist())
    if isinstance(v, (list, tuple)):
        return [_plain(x) for x in v]
    if isinstance(v, (np.floating, float)) and not isinstance(v, bool):
        v = float(v)
        return v if math.isfinite(v) else repr(v)
    if isinstance(v, np.integer):
        return int(v)
    if isinstance(v, np.bool_):
        return bool(v)
    return v


_BALL_KEYS = ("x", "v", "p", "r", "m", "tau", "tau_last", "image")


def balls_from_arrays(cols, where="balls"):
    """A dict of arrays {"x": (N, dim), "v" or "p": (N, dim), "r", "m", "tau",
    "tau_last" (NaN: no collision yet): (N,) or scalars, "image": (N, dim)} as the list of
    ball objects of a scenario. Lengths must agree (ValueError naming the key)."""
    unknown = set(cols) - set(_BALL_KEYS)
    if unknown:
        raise ScenarioError("Sim: %s.%s: unknown key (expected one of: %s)"
                            % (where, sorted(unknown)[0], ", ".join(_BALL_KEYS)))
    if "x" not in cols:
        raise ScenarioError("Sim: %s.x: missing (required)" % where)
    x = np.asarray(cols["x"], dtype=float)
    if x.ndim != 2:
        raise ScenarioError("Sim: %s.x: must be an (N, dim) array, not of shape %s"
                            % (where, x.shape))
    n = len(x)
    out = {"x": x.tolist()}
    for k in _BALL_KEYS[1:]:
        if k not in cols:
            continue
        a = np.asarray(cols[k], dtype=np.int64 if k == "image" else float)
        vector = k in ("v", "p", "image")
        want = (n, x.shape[1]) if vector else (n,)
        if a.shape != want and not (not vector and a.ndim == 0):
            raise ScenarioError("Sim: %s.%s: has shape %s, %s.x (N, dim) = %s wants %s%s"
                                % (where, k, a.shape, where, x.shape, want,
                                   "" if vector else " or a scalar"))
        out[k] = np.broadcast_to(a, want)
    balls = []
    for i in range(n):
        b = {}
        for k, a in out.items():
            v = a[i] if k == "x" else a[i].tolist()
            if k == "tau_last" and math.isnan(v):
                continue
            b[k] = v
        balls.append(b)
    return balls


# a Sim has no end unless the scenario gives one: the reader's required t_end is then
# the largest double, and the outputs block (a Sim writes no files) is not read
_NO_END = sys.float_info.max


class Scenario:
    """A parsed scenario (scn_scenario): what the C reader made of the text, kept for
    the engine's definition, its start and scn_save."""

    def __init__(self, s, name="Sim", base=None):
        s = dict(s)
        if isinstance(s.get("balls"), dict):
            s["balls"] = balls_from_arrays(s["balls"])
        self.has_end = "t_end" in s
        if not self.has_end:
            s["t_end"] = _NO_END
            s.pop("outputs", None)
        if "checkpoint" in s and s["checkpoint"] is None:
            del s["checkpoint"]  # (start afresh from the balls)
        # the field: checked here by name; along the last axis the reader takes it (its rules,
        # its messages), along another one it is set on the parsed scenario (the reader's
        # "gravity" key has the last axis only), with the reader's default frame in a field
        self.field_axis, field, to_c = None, None, s
        if s.get("gravity") is not None:
            from .field import check_gravity
            dim = s.get("dim")
            known = isinstance(dim, int) and not isinstance(dim, bool) and dim in (2, 3)
            grav = s["gravity"] if known else {k: v for k, v in s["gravity"].items()
                                               if k != "axis"} if isinstance(s["gravity"], dict) else s["gravity"]
            g, cp, axis = check_gravity(grav, dim if known else 0, name)
            to_c = dict(s)
            if axis is None or axis == dim - 1:
                to_c["gravity"] = {"g": g, "coupling": cp}
                self.field_axis = axis
            else:
                del to_c["gravity"]
                to_c.setdefault("contact_frame", "sphere")
                field, self.field_axis = (g, cp), axis
        text = json.dumps(_plain(to_c), allow_nan=False)
        self.name = name
        # the file whose folder holds the checkpoint it names
        self.file = base if base is not None else os.path.join(os.getcwd(), "scenario.json")
        self._raw = ffi.new("scn_scenario *")
        err = ffi.new("char[]", lib.APP_ERR_LEN)
        if lib.scn_parse(text.encode(), name.encode(), self._raw, err) != 0:
            raise ScenarioError(ffi.string(err).decode())
        self.ptr = ffi.gc(self._raw, lib.scn_free)
        self.dict = s
        if field is not None:
            self._field_across(name, *field)

    def _field_across(self, name, g, coupling):
        """The field along an axis other than the last, set on the parsed scenario, with the
        reader's rules for the field's axis and frame."""
        p, ax = self.ptr, self.field_axis
        if p.boundary[ax] != lib.RC_SIM_WALLS:
            raise ScenarioError("%s: gravity.axis: axis %d is periodic: the field's axis must "
                                "have walls (its floor and ceiling)" % (name, ax))
        f = p.frame
        if f.contracted or f.pointlike or f.per_ball or f.wall_contracted:
            raise ScenarioError("%s: contact_frame: frame '%s' is not defined in a field (the "
                                "field takes one-instant uncontracted frames: sphere; "
                                "papers/gravity.md, model limits)"
                                % (name, ffi.string(f.name).decode()))
        p.gravity = lib.rc_gravity_find(coupling.encode())
        p.g = g

    @property
    def t_end(self):
        return self.ptr.t_end if self.has_end else None

    def balls(self):
        """The scenario's balls as arrays (x, p, r, m) in its dimension."""
        n, dim = self.ptr.n, self.ptr.dim
        b = ffi.buffer(self.ptr.balls, n * ffi.sizeof("rc_sim_ball"))
        rec = np.frombuffer(b, dtype=_BALL_DTYPE, count=n)
        return {"x": rec["x"][:, :dim].copy(), "p": rec["p"][:, :dim].copy(),
                "r": rec["r"].copy(), "m": rec["m"].copy()}


def _ball_dtype():
    """rc_sim_ball's layout as a numpy record, read from the compiled module's offsets."""
    names, formats, offsets = [], [], []
    for name, fmt in (("x", ("f8", 3)), ("p", ("f8", 3)), ("r", "f8"), ("m", "f8"),
                      ("tau", "f8"), ("collided", "i4"), ("tau_last", "f8"),
                      ("image", ("i4", 3))):
        names.append(name)
        formats.append(fmt)
        offsets.append(ffi.offsetof("rc_sim_ball", name))
    return np.dtype({"names": names, "formats": formats, "offsets": offsets,
                     "itemsize": ffi.sizeof("rc_sim_ball")})


_BALL_DTYPE = _ball_dtype()


def parse(source, overrides=None, name=None):
    """A Scenario from a dict, a path or JSON text, with keyword overrides."""
    base = None
    if isinstance(source, (str, os.PathLike)) and not str(source).lstrip().startswith("{"):
        base = os.path.abspath(str(source))
        name = name or str(source)
    s = load_scenario(source) if source is not None else {}
    s.update(overrides or {})
    return Scenario(s, name or "Sim", base)
