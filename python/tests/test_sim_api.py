"""relcol.Sim as a REBOUND user works with it (issue 38, item 1): C-filled state arrays
equal to the bit to a per-ball read through the library; checkpoints through Python that
continue exactly as relcol-sim's do, both ways; set_c, add, steps/events; the readers of
relcol-sim's outputs."""
import json
import os
import subprocess

import numpy as np
import pytest

import relcol
from relcol._relcol import ffi, lib

SIM = os.environ.get("RELCOL_SIM")
needs_sim = pytest.mark.skipif(SIM is None, reason="relcol-sim not given")


def gas(frame="table", c=1.0, n=200, seed=3, **kw):
    box, balls = relcol.gas_init(2, n, 1.0, 0.3, 0.5, c=c, seed=seed)
    return relcol.Sim(dim=2, box=box, c=c, balls=balls, contact_frame=frame,
                      boundary="periodic", **kw)


def per_ball(sim, get=lib.rc_sim_get_ball):
    """The state read ball by ball through the library (the reference the C fill must
    equal): x, p, r, m, tau, image."""
    b = ffi.new("rc_sim_ball *")
    rows = []
    for i in range(sim.n):
        assert get(sim._sim, i, b) == 0
        rows.append([b.x.x, b.x.y, b.p.x, b.p.y, b.r, b.m, b.tau, b.image[0], b.image[1]])
    a = np.array(rows)
    return {"x": a[:, 0:2], "p": a[:, 2:4], "r": a[:, 4], "m": a[:, 5], "tau": a[:, 6],
            "image": a[:, 7:9]}


@pytest.mark.parametrize("frame", ["table", "covariant"])
def test_c_filled_reads_equal_per_ball_reads(frame):
    sim = gas(frame).advance(5.0)
    st, ref = sim.state(), per_ball(sim)
    for k in ref:
        assert np.array_equal(st[k], ref[k]), k
    assert np.array_equal(sim.positions, ref["x"]) and np.array_equal(sim.momenta, ref["p"])
    assert np.array_equal(sim.radii, ref["r"]) and np.array_equal(sim.rest_masses, ref["m"])
    assert np.array_equal(sim.proper_times, ref["tau"])
    assert np.array_equal(sim.images, ref["image"])
    if frame == "covariant":  # (kinks ahead only in a per_ball frame)
        want = [lib.rc_sim_kink_ahead(sim._sim, i) for i in range(sim.n)]
        assert np.array_equal(st["kink_ahead"], want) and max(want) >= 0
    lt = sim.state(latest=True)
    ref_l = per_ball(sim, lib.rc_sim_get_ball_latest)
    for k in ref_l:
        assert np.array_equal(lt[k], ref_l[k]), k
    # v = p / M with M = sqrt(m^2 + p^2/c^2): the kinematics module's, to round-off
    assert np.allclose(sim.velocities, relcol.velocity(st["m"], st["p"], sim.c), rtol=1e-15)


def test_python_checkpoint_round_trip_is_bit_identical(tmp_path):
    # a run stopped at t = 4, saved, loaded and continued to 9 equals the run that never
    # stopped, in every bit (the covariant frame: its kinks ahead live in the checkpoint)
    whole = gas("covariant").advance(9.0)
    part = gas("covariant").advance(4.0)
    path = part.save(tmp_path / "state.json")
    assert (tmp_path / "state.ckpt").exists()
    cont = relcol.Sim.load(path)
    assert cont.time == 4.0 and cont.hash() == part.hash()
    cont.advance(9.0)
    assert cont.hash() == whole.hash()
    for k in ("x", "p", "tau", "m"):
        assert np.array_equal(cont.state()[k], whole.state()[k])
    # the bytes alone, into a Sim of the same definition
    other = gas("covariant")
    other.restore(part.checkpoint()).advance(9.0)
    assert other.hash() == whole.hash()
    with pytest.raises(relcol.RelcolError) as e:
        other.restore(part.checkpoint()[:-3])
    assert e.value.name == "RC_ECORRUPT"


@needs_sim
def test_checkpoints_continue_as_relcol_sim_both_ways(tmp_path):
    scn = {"relcol": 1, "dim": 2, "c": 1, "contact_frame": "covariant", "seed": 5,
           "boundary": "periodic", "t_end": 3,
           "generate": {"kind": "gas", "n": 150, "radius": 1, "packing": 0.3, "v_rms": 0.6},
           "outputs": {"plots": False, "gif": False}}
    path = tmp_path / "gas.json"
    path.write_text(json.dumps(scn))
    run = lambda f, out: subprocess.run([SIM, str(f), "--out", str(out), "--no-plots"],
                                        check=True, capture_output=True)
    run(path, tmp_path / "a")                       # relcol-sim to 3
    run(tmp_path / "a" / "final.json", tmp_path / "b")  # relcol-sim from 3 to 6
    want = json.load(open(tmp_path / "b" / "final.json"))
    # relcol-sim's final.json continued by Python (with its checkpoint)
    sim = relcol.Sim(str(tmp_path / "a" / "final.json"))
    assert sim.time == 3.0
    sim.run()
    assert sim.time == want["time"] == 6.0
    for k in ("x", "p", "tau"):
        assert np.array_equal(sim.state()[k], np.array([b[k] for b in want["balls"]])), k
    # Python's save continued by relcol-sim
    py = relcol.Sim(str(path)).run()
    py.save(tmp_path / "py.json")
    run(tmp_path / "py.json", tmp_path / "c")
    got = json.load(open(tmp_path / "c" / "final.json"))
    assert got["time"] == 6.0
    for k in ("x", "p", "tau"):
        assert [b[k] for b in got["balls"]] == [b[k] for b in want["balls"]], k
    # a checkpoint that is not the balls' state is refused, as relcol-sim refuses it
    bad = json.load(open(tmp_path / "a" / "final.json"))
    bad["balls"][2]["x"][0] += 1e-9
    (tmp_path / "a" / "bad.json").write_text(json.dumps(bad))
    with pytest.raises(relcol.ScenarioError, match=r"balls\[2\]: differs from the state in the "
                                                   r"checkpoint"):
        relcol.Sim(str(tmp_path / "a" / "bad.json"))
    # checkpoint=None: afresh from the balls
    relcol.Sim(str(tmp_path / "a" / "bad.json"), checkpoint=None)


def test_set_c_keeps_momenta_and_conserves():
    sim = gas("table", c=float("inf"))
    sim.advance(3.0)
    p, m = sim.momenta, sim.rest_masses
    sim.set_c(0.8)
    assert sim.c == 0.8 and np.array_equal(sim.momenta, p) and np.array_equal(sim.rest_masses, m)
    v = np.linalg.norm(sim.velocities, axis=1)
    assert (v < 0.8).all()
    d0 = sim.diagnostics()
    sim.advance(8.0)
    d = sim.diagnostics()
    assert d["collisions"] > d0["collisions"] + 50
    # energy at the new c (kinetic + heat, elastic: kinetic) is kept from the switch on
    e1 = sim.diagnostics()["energy"]
    assert abs(e1 - d0["energy"]) <= 1e-12 * e1
    with pytest.raises(relcol.RelcolError, match="set_c"):
        sim.set_c(-1)


def test_add_balls():
    sim = relcol.Sim(dim=2, box=[10, 10], c=2.0, balls=[{"x": [2, 5], "v": [1, 0], "r": 0.5}])
    sim.add(x=[8, 5], v=[-1, 0], r=0.5)
    sim.add({"x": [[5, 2], [5, 8]], "v": [[0, 1], [0, -1]], "r": 0.4})
    assert sim.n == 4 and np.array_equal(sim.radii, [0.5, 0.5, 0.4, 0.4])
    with pytest.raises(relcol.ScenarioError, match=r"add: balls\[0\]: overlaps another ball"):
        sim.add(x=[2.2, 5], r=0.5)
    with pytest.raises(relcol.ScenarioError, match=r"add: balls\[0\]\.v: \|v\| = 3 >= c = 2"):
        sim.add(x=[1, 1], v=[3, 0], r=0.2)
    assert sim.n == 4
    sim.advance(10)
    d = sim.diagnostics()
    assert d["collisions"] >= 2 and abs(d["energy_error"]) < 1e-14


def test_steps_and_events():
    sim = gas("table", n=50)
    times = [s.time for s in sim.steps(0.5, 2.0)]
    assert times == [0.5, 1.0, 1.5, 2.0]
    ref = gas("table", n=50).advance(2.0)
    assert sim.hash() == ref.hash()  # sampling does not change the run
    seen = []
    sim.integrate(3.0, every="event", callback=lambda s: seen.append(s.time))
    ev = sim.diagnostics()["events"]
    assert len(seen) >= sum(ev.values()) - sum(ref.diagnostics()["events"].values())
    assert seen == sorted(seen) and seen[-1] == 3.0
    assert sim.hash() == gas("table", n=50).advance(3.0).hash()


@needs_sim
def test_readers_of_relcol_sim_outputs(tmp_path):
    h5py = pytest.importorskip("h5py")
    scn = {"relcol": 1, "dim": 2, "c": 1, "seed": 2, "t_end": 2,
           "generate": {"kind": "gas", "n": 60, "radius": 1, "packing": 0.2, "v_rms": 0.5},
           "outputs": {"snapshots": [1, 2], "h5md_every": 0.5, "plots": False, "gif": False}}
    (tmp_path / "s.json").write_text(json.dumps(scn))
    subprocess.run([SIM, str(tmp_path / "s.json"), "--out", str(tmp_path / "o"),
                    "--no-plots"], check=True, capture_output=True)
    run = relcol.read_run(str(tmp_path / "o"))
    final = run["final"]
    snap = run["snapshots"][-1]
    assert [s["t"] for s in run["snapshots"]] == [1.0, 2.0]
    assert np.array_equal(snap["x"], [b["x"] for b in final["balls"]])
    assert np.array_equal(snap["p"], [b["p"] for b in final["balls"]])
    assert run["summary"]["collisions"]["contacts"] > 0
    h5 = run["h5md"]["particles"]["all"]
    pos = h5["position"]
    assert pos["value"].shape == (5, 60, 2) and np.array_equal(pos["time"], [0, .5, 1, 1.5, 2])
    assert np.array_equal(pos["value"][-1], snap["x"])
    with h5py.File(tmp_path / "o" / "trajectory.h5") as f:
        assert np.array_equal(f["particles/all/position/value"][2], pos["value"][2])
    sim = relcol.Sim(dict(scn, outputs={})).run()
    assert np.array_equal(sim.positions, snap["x"])
