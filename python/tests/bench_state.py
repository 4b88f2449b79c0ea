"""bench_state.py — reading a Sim's state against advancing it (issue 38: reading <= 10 %
of an advance of 10^3 collisions at N = 2 10^4). A 2-D gas of N balls at packing 0.3,
c = 1, melted first; then, best of 7: the time of advance() over the next ~10^3
collisions, of state() (every array, filled in C in one call) and of one property
(positions). Prints the figures and the ratios; the goal is <= 0.1. No verdict (exit 0).
Usage: bench_state.py [N [reps]]."""
import sys
import time

import relcol


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 20000
    reps = int(sys.argv[2]) if len(sys.argv) > 2 else 7
    box, balls = relcol.gas_init(2, n, 1.0, 0.3, 0.5, c=1.0, seed=1)
    sim = relcol.Sim(dim=2, box=box, c=1.0, balls=balls, boundary="periodic")
    sim.advance(2.0)
    # the table time that holds about 10^3 collisions, from the rate so far
    rate = sim.diagnostics()["collisions"] / (sim.time - 0.0)
    dt = 1000.0 / rate
    c0 = sim.diagnostics()["collisions"]
    sim.advance(sim.time + dt)  # (the melted gas collides faster: dt calibrated on it)
    dt *= 1000.0 / max(sim.diagnostics()["collisions"] - c0, 1)
    best = {"advance": 1e300, "state": 1e300, "positions": 1e300}
    hits = 0
    for _ in range(reps):
        c0 = sim.diagnostics()["collisions"]
        t0 = time.perf_counter()
        sim.advance(sim.time + dt)
        best["advance"] = min(best["advance"], time.perf_counter() - t0)
        hits = sim.diagnostics()["collisions"] - c0
        t0 = time.perf_counter()
        sim.state()
        best["state"] = min(best["state"], time.perf_counter() - t0)
        t0 = time.perf_counter()
        sim.positions
        best["positions"] = min(best["positions"], time.perf_counter() - t0)
    print("bench_python_state: N = %d, 2-D, c = 1, packing 0.3, best of %d" % (n, reps))
    print("  advance (%d collisions)   %9.3f ms" % (hits, 1e3 * best["advance"]))
    for k in ("state", "positions"):
        r = best[k] / best["advance"]
        print("  %-24s  %9.3f ms  ratio to advance %.3f (goal <= 0.1: %s)"
              % (k + "()" if k == "state" else k, 1e3 * best[k], r, "met" if r <= 0.1 else "NOT met"))


if __name__ == "__main__":
    main()
