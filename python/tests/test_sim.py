"""relcol.Sim: the same run as relcol-sim from the same scenario (every bit), arrays in
and out, conservation, and scenario errors."""
import json
import math
import os
import subprocess

import numpy as np
import pytest

import relcol

SOURCE = os.environ.get("RELCOL_SOURCE", os.path.join(os.path.dirname(__file__), "..", ".."))
RACK = os.path.join(SOURCE, "data", "scenarios", "rack.json")


@pytest.mark.skipif("RELCOL_SIM" not in os.environ, reason="relcol-sim not given")
def test_rack_equals_relcol_sim(tmp_path):
    subprocess.run([os.environ["RELCOL_SIM"], RACK, "--out", str(tmp_path / "o"), "--no-plots"],
                   check=True, capture_output=True)
    with open(tmp_path / "o" / "final.json") as f:
        final = json.load(f)
    sim = relcol.Sim(RACK).run()
    st = sim.state()
    assert st["t"] == final["time"]
    want_x = np.array([b["x"] for b in final["balls"]])
    want_p = np.array([b["p"] for b in final["balls"]])
    want_tau = np.array([b["tau"] for b in final["balls"]])
    # relcol-sim writes round-trip decimals: equal doubles, not merely close ones
    assert np.array_equal(st["x"], want_x) and np.array_equal(st["p"], want_p)
    assert np.array_equal(st["tau"], want_tau)
    summary = json.load(open(tmp_path / "o" / "summary.json"))
    d = sim.diagnostics()
    assert d["collisions"] == summary["collisions"]["contacts"]
    assert d["energy_error"] == pytest.approx(summary["energy_error"], abs=1e-300)
    # relcol-sim's final state reads back as a scenario (balls, time, TC memory)
    cont = relcol.Sim(str(tmp_path / "o" / "final.json"), checkpoint=None)
    assert cont.time == final["time"] and np.array_equal(cont.positions, want_x)
    assert np.array_equal(cont.proper_times, want_tau)


def test_gas_from_arrays_conserves_and_is_deterministic():
    box, balls = relcol.gas_init(2, 100, 1.0, 0.3, 0.5, c=1.0, seed=3)
    runs = []
    for _ in range(2):
        sim = relcol.Sim(dim=2, box=box, c=1.0, balls=balls, contact_frame="zmf",
                         boundary="periodic")
        sim.advance(20.0)
        runs.append(sim)
    d = runs[0].diagnostics()
    assert runs[0].hash() == runs[1].hash()
    assert d["collisions"] > 100
    # energy (kinetic + heat) is a sum over 100 balls updated by exact-conservation
    # kernels: round-off of order 1e-15 per collision, relative
    assert abs(d["energy_error"]) < 1e-12 and d["momentum_error"] < 1e-12
    st = runs[0].state()
    assert st["x"].shape == (100, 2) and st["p"].shape == (100, 2)
    assert (st["tau"] < runs[0].time).all() and (st["tau"] > 0).all()
    assert (np.linalg.norm(st["v"], axis=1) < 1.0).all()
    assert np.array_equal(runs[0].rest_masses, balls["m"])  # elastic: rest masses kept
    # proper time lags table time by the mean 1/gamma: for speeds ~0.5 c, 0.7..0.99
    assert 0.6 * 20 < st["tau"].mean() < 20


def test_ball_list_velocities_and_walls():
    sim = relcol.Sim({"dim": 2, "box": [10, 10], "c": 2, "restitution": {"ball": 0.5},
                      "balls": [{"r": 1, "x": [2, 5], "v": [1.5, 0]},
                                {"r": 1, "x": [8, 5], "v": [-1.5, 0]}]})
    sim.advance(10)
    d = sim.diagnostics()
    assert d["events"]["ball"] >= 1 and d["heat"] > 0
    assert (sim.rest_masses > 1).all()  # inelastic: heat became rest mass
    assert abs(d["energy_error"]) < 1e-14


def test_scenario_errors():
    with pytest.raises(ValueError, match="colour: unknown key"):
        relcol.Sim(RACK, colour="red")
    with pytest.raises(relcol.ScenarioError, match=r"balls\[0\]\.v: \|v\| = 1 >= c = 1"):
        relcol.Sim(dim=2, box=[4, 4], c=1, balls={"x": [[1, 1]], "v": [[1.0, 0]], "r": 0.5})
    with pytest.raises(relcol.ScenarioError, match=r"balls\[1\]: overlaps another ball"):
        relcol.Sim(dim=2, box=[4, 4], balls={"x": [[1, 1], [1.5, 1]], "r": 0.5})
    with pytest.raises(relcol.ScenarioError, match="law: unknown collision law 'newton'"):
        relcol.Sim(RACK, law="newton")


def test_ball_numbers_out_of_range_are_refused_as_relcol_sim_refuses_them():
    # The fuzzer's input (tests/fuzz/regress): a gas of radius 4.5e67 has rest masses
    # r^3 = 8.9e202 whose squares overflow; relcol-sim refuses it naming generate.radius.
    reg = os.path.join(SOURCE, "tests", "fuzz", "regress", "gas-radius-mass-overflow.json")
    with pytest.raises(ValueError, match=r"generate\.radius: gives ball 0 a rest mass out of range"):
        relcol.Sim(reg)
    if "RELCOL_SIM" in os.environ:
        out = subprocess.run([os.environ["RELCOL_SIM"], reg, "--out", os.devnull],
                             capture_output=True, text=True)
        assert out.returncode != 0 and "generate.radius" in out.stderr
    with pytest.raises(ValueError, match=r"balls\[1\]\.x\[1\]: 1e-200 is too small"):
        relcol.Sim(dim=2, box=[4, 4], balls=[{"x": [1, 1], "r": 0.5},
                                             {"x": [3, 1e-200], "r": 0.5}])
    with pytest.raises(ValueError, match=r"balls\[0\]\.r: 1e-160 is too small"):
        relcol.Sim(dim=2, box=[4, 4], balls={"x": [[1, 1]], "r": 1e-160, "m": 1.0})
    # zero positions and momenta are in range
    relcol.Sim(dim=2, box=[4, 4], balls={"x": [[1, 1]], "p": [[0.0, 0.0]], "r": 0.5})


def test_covariant_frame_counts_its_conflicts():
    box, balls = relcol.gas_init(2, 100, 1.0, 0.3, 0.5, c=1.0, seed=3)
    sim = relcol.Sim(dim=2, box=box, c=1.0, balls=balls, contact_frame="covariant",
                     boundary="periodic")
    sim.advance(20.0)
    d = sim.diagnostics()
    assert d["collisions"] > 100
    assert abs(d["energy_error"]) < 1e-12 and d["momentum_error"] < 1e-12
    # the per-ball conflicts are counted, and a tube conflict is an overlap-policy contact
    assert 0 <= d["tube_conflicts"] <= d["overlaps"] and d["order_conflicts"] >= 0
    # collisions undone (papers/covariant-frame.md section 2) are not policy decisions: a
    # conflict it undoes leaves no overlap behind (rollbacks + overlaps <= contacts)
    assert d["rollbacks"] > 0 and d["rollbacks"] + d["overlaps"] <= d["collisions"]
    zmf = relcol.Sim(dim=2, box=box, c=1.0, balls=balls, contact_frame="zmf",
                     boundary="periodic")
    zmf.advance(20.0)
    assert zmf.diagnostics()["tube_conflicts"] == 0 == zmf.diagnostics()["order_conflicts"]
    assert zmf.diagnostics()["rollbacks"] == 0


def test_covariant_state_reads_kinks_ahead():
    # a ball whose kink lies after the engine's time is read on its incoming line
    # (kink_ahead 1); latest=True gives every ball's latest segment, whose momenta sum to
    # the conserved total
    box, balls = relcol.gas_init(2, 100, 1.0, 0.3, 0.5, c=1.0, seed=3)
    sim = relcol.Sim(dim=2, box=box, c=1.0, balls=balls, contact_frame="covariant",
                     boundary="periodic")
    p0 = sim.state()["p"].sum(axis=0)
    seen = 0
    for _ in range(400):
        sim.advance(1e300, max_events=1)
        st, lt = sim.state(), sim.state(latest=True)
        ahead = st["kink_ahead"] > 0
        seen += int(ahead.sum())
        assert np.array_equal(st["p"][~ahead], lt["p"][~ahead])
        assert not np.array_equal(st["p"][ahead], lt["p"][ahead]) or not ahead.any()
        assert np.allclose(lt["p"].sum(axis=0), p0, atol=1e-12 * np.abs(lt["p"]).sum())
    assert seen > 0


def test_slices():
    # a delayed slice: in the zmf frame the state a second run has at t, bit for bit; in
    # the covariant frame refused (RC_ENOTREADY) until the engine is past t + W, then read
    box, balls = relcol.gas_init(2, 100, 1.0, 0.3, 0.5, c=1.0, seed=3)
    a = relcol.Sim(dim=2, box=box, c=1.0, balls=balls, contact_frame="zmf",
                   boundary="periodic")
    b = relcol.Sim(dim=2, box=box, c=1.0, balls=balls, contact_frame="zmf",
                   boundary="periodic")
    sid = b.slice_request(3.0)
    b.advance(6.0)
    sl = b.slice_state(sid, release=True)
    st = a.advance(3.0).state()
    for k in ("x", "p", "m", "tau", "image"):
        assert np.array_equal(sl[k], st[k])
    with pytest.raises(relcol.RelcolError) as e:
        b.slice_ready(sid)
    assert e.value.name == "RC_ENOSLICE"
    cov = relcol.Sim(dim=2, box=box, c=1.0, balls=balls, contact_frame="covariant",
                     boundary="periodic")
    sid = cov.slice_request(2.0)
    cov.advance(2.5)
    info = cov.slice_ready(sid)
    assert not info["final"] and info["t_final"] > 2.5
    with pytest.raises(relcol.RelcolError) as e:
        cov.slice_state(sid)
    assert e.value.name == "RC_ENOTREADY"
    while not info["final"]:  # (t_final grows while the run makes faster balls)
        cov.advance(info["t_final"])
        info = cov.slice_ready(sid)
    sl = cov.slice_state(sid)
    assert sl["t"] == 2.0 and cov.slice_ready(sid)["late"] == 0
    assert sl["x"].shape == (100, 2) and np.all((sl["x"] >= 0) & (sl["x"] < box[0]))


def test_diagnostics_model_block():
    # the validity report (relcol/validity.h), as summary.json's model block: the dense
    # covariant gas is outside the rigid-ball model's regime, the zmf frame is a
    # non-covariant model, c = inf is defined
    box, balls = relcol.gas_init(2, 100, 1.0, 0.3, 0.5, c=1.0, seed=3)
    keys = {"verdict", "threshold_p_model", "covariant", "p_model", "p_all",
            "largest_cluster", "largest_cluster_all", "nu_r_c", "policy_share", "policy",
            "collisions", "tube_conflicts", "order_conflicts", "undone", "kink_events",
            "kink_pairs", "kink_pairs_model", "crossing", "crossing_model"}
    for frame, want in (("covariant", "outside"), ("zmf", "non_covariant")):
        sim = relcol.Sim(dim=2, box=box, c=1.0, balls=balls, contact_frame=frame,
                         boundary="periodic")
        sim.advance(20.0)
        m = sim.diagnostics()["model"]
        assert set(m) == keys and m["verdict"] == want and m["threshold_p_model"] == 1e-3
        assert (m["p_model"] > 1e-3) == (want == "outside")
        assert m["policy"] == sim.diagnostics()["overlaps"]
    box, balls = relcol.gas_init(2, 100, 1.0, 0.3, 0.5, c=math.inf, seed=3)
    sim = relcol.Sim(dim=2, box=box, c=math.inf, balls=balls, boundary="periodic")
    sim.advance(5.0)
    assert sim.diagnostics()["model"]["verdict"] == "defined"


@pytest.mark.parametrize("coupling", ["newtonian", "equivalence"])
def test_gravity_scenario_field_energy_and_refusals(coupling):
    # a scenario with "gravity" through the C reader: h - booked (rc_sim_field_energy) kept
    # to round-off (papers/gravity.md section 4), the balls above the floor; a delayed slice
    # refused in the field (RC_EUNDEFINED), field_energy refused without one (RC_EINVAL)
    scn = {"relcol": 1, "dim": 2, "c": 2, "t_end": 20, "seed": 3,
           "boundary": ["periodic", "walls"],
           "gravity": {"g": 0.05, "coupling": coupling},
           "generate": {"kind": "gas", "n": 100, "radius": 0.5, "packing": 0.05, "v_rms": 0.5}}
    s = relcol.Sim(scn)
    h0, w0 = s.field_energy()
    s.run()
    h, w = s.field_energy()
    assert s.diagnostics()["collisions"] > 100
    assert abs((h - w) - (h0 - w0)) <= 1e-10 * abs(h0)
    assert np.all(s.state()["x"][:, 1] > 0)
    with pytest.raises(relcol.RelcolError) as e:
        s.slice_request(s.time + 1.0)
    assert e.value.name == "RC_EUNDEFINED" and "gravity" in str(e.value)
    box, balls = relcol.gas_init(2, 20, 1.0, 0.3, 0.5, c=1.0, seed=3)
    free = relcol.Sim(dim=2, box=box, c=1.0, balls=balls, boundary="periodic")
    with pytest.raises(relcol.RelcolError) as e:
        free.field_energy()
    assert e.value.name == "RC_EINVAL"
