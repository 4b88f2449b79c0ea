"""Sim.positions, the library's lean read (rc_sim_get_positions), against the full read
ball by ball (rc_sim_get_ball) and state()'s x, to the bit: periodic and walled boxes,
the table and the covariant (per-ball, kinks ahead) frames, and a uniform field's curved
paths (engine/path.h) with walls."""
import os

import numpy as np
import pytest

import relcol
from relcol import _ffi as ffi, _lib as lib

SOURCE = os.environ.get("RELCOL_SOURCE", os.path.join(os.path.dirname(__file__), "..", ".."))


def full(sim, get=lib.rc_sim_get_ball):
    b = ffi.new("rc_sim_ball *")
    x = np.empty((sim.n, sim.dim))
    for i in range(sim.n):
        assert get(sim._sim, i, b) == 0
        x[i] = [b.x.x, b.x.y, b.x.z][:sim.dim]
    return x


def gas(frame, boundary, c=1.0):
    box, balls = relcol.gas_init(2, 300, 1.0, 0.3, 0.5, c=c, seed=5)
    return relcol.Sim(dim=2, box=box, c=c, balls=balls, contact_frame=frame,
                      boundary=boundary)


def same_bits(a, b):
    return a.shape == b.shape and a.tobytes() == b.tobytes()


def lean(sim, latest):
    x = np.empty((sim.n, sim.dim))
    assert lib.rc_sim_get_positions(sim._sim, sim.n, sim.dim, ffi.from_buffer("double[]", x),
                                    latest) == 0
    return x


@pytest.mark.parametrize("frame", ["table", "covariant"])
@pytest.mark.parametrize("boundary", ["periodic", "walls"])
def test_lean_equals_full(frame, boundary):
    sim = gas(frame, boundary)
    for t in (0.0, 0.37, 1.5, 3.25):
        sim.advance(t)
        x = sim.positions
        assert same_bits(x, full(sim)), (frame, boundary, t)
        assert same_bits(x, sim.state()["x"])
        assert same_bits(lean(sim, 1), full(sim, lib.rc_sim_get_ball_latest))
    if frame == "covariant":  # (the case the lean path hands to the full read)
        assert sim.state()["kink_ahead"].any()


def test_lean_in_a_field():
    sim = relcol.Sim(os.path.join(SOURCE, "data", "scenarios", "atmosphere.json"))
    for t in (0.5, 7.25, 40.0):
        sim.advance(t)
        assert same_bits(sim.positions, full(sim)), t
        assert same_bits(lean(sim, 1), full(sim, lib.rc_sim_get_ball_latest))


def test_lean_refuses_wrong_sizes():
    sim = gas("table", "periodic")
    x = np.empty((sim.n + 1, 3))
    buf = ffi.from_buffer("double[]", x)
    assert lib.rc_sim_get_positions(sim._sim, sim.n + 1, 2, buf, 0) == -1  # RC_EINVAL
    assert lib.rc_sim_get_positions(sim._sim, sim.n, 3, buf, 0) == -1  # RC_EINVAL
    assert lib.rc_sim_get_positions(ffi.NULL, 0, 2, buf, 0) == -1  # RC_EINVAL
