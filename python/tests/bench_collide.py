"""bench_collide.py — relcol.collide over 1e6 pairs against bench_law's C rate.

The same work as tests/law/bench_law.c counts: 3-D, c = 1, eps = 0.8, the zmf law,
masses log-uniform in [0.1, 10], speeds below 0.95 c, normals oriented so that every pair
approaches; best of 7 timings of one call, pairs per second. The Python figure times the
whole call (every pair with rc_collide's checks and the kernel, rc_collide_columns, read
from the caller's arrays and written into new result arrays: views of an output block that
laws.py reuses once no array of an earlier result is alive, here the call before last's),
from numpy arrays in to numpy arrays out. Usage: bench_collide.py BENCH_LAW [n_pairs [reps]].
Prints figures and the ratio to the C rate; the goal is >= 0.5. No verdict (exit 0)."""
import re
import subprocess
import sys
import time

import numpy as np

import relcol


def main():
    bench_law = sys.argv[1]
    n = int(sys.argv[2]) if len(sys.argv) > 2 else 1000000
    reps = int(sys.argv[3]) if len(sys.argv) > 3 else 7
    rng = np.random.default_rng(2024)

    def vel():
        u = rng.normal(size=(n, 3))
        u /= np.linalg.norm(u, axis=1)[:, None]
        return u * (0.95 * rng.uniform(size=n))[:, None]

    v0, v1 = vel(), vel()
    nn = rng.normal(size=(n, 3))
    nn /= np.linalg.norm(nn, axis=1)[:, None]
    nn[np.sum((v0 - v1) * nn, axis=1) < 0] *= -1
    m0 = np.exp(rng.uniform(np.log(0.1), np.log(10), n))
    m1 = np.exp(rng.uniform(np.log(0.1), np.log(10), n))
    p0, p1 = relcol.momentum(m0, v0, 1.0), relcol.momentum(m1, v1, 1.0)
    best = 1e300
    for _ in range(reps):
        t0 = time.perf_counter()
        out = relcol.collide(m0, p0, m1, p1, nn, c=1.0, eps=0.8, law="zmf")
        best = min(best, time.perf_counter() - t0)
    rate_py = n / best
    text = subprocess.run([bench_law, str(n), str(reps)], check=True, capture_output=True,
                          text=True).stdout
    rate_c = 1e6 * float(re.search(r"zmf, c = 1 \(relativistic\)\s+([0-9.]+) M pairs/s",
                                   text).group(1))
    print("bench_python_collide: %d pairs, 3-D, c = 1, eps = 0.8, zmf, best of %d" % (n, reps))
    print("  relcol.collide (Python)     %8.2f M pairs/s  (%5.2f ns/pair, %d collided)"
          % (rate_py / 1e6, 1e9 / rate_py, int(out.collided.sum())))
    print("  rc_collide_batch (C)        %8.2f M pairs/s  (bench_law, same process count)"
          % (rate_c / 1e6))
    # the library's validating batch over columns
    many = re.search(r"rc_collide_many\s+([0-9.]+) M pairs/s", text)
    if many:
        print("  rc_collide_many (C)         %8.2f M pairs/s  (the library's checked batch)"
              % float(many.group(1)))
    print("  ratio Python / C            %8.2f  (goal >= 0.5: %s)"
          % (rate_py / rate_c, "met" if rate_py / rate_c >= 0.5 else "NOT met"))
    if many:
        print("  ratio Python / rc_collide_many %5.2f" % (rate_py / (1e6 * float(many.group(1)))))


if __name__ == "__main__":
    main()
