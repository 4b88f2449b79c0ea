#!/usr/bin/python3
"""aim_kill.py SIM SCENARIO DIR DELAY_US — for test_sim_publish.sh: runs SIM SCENARIO --out DIR,
watches DIR until the run's staging folder (.run.relcol-PID.*) holds summary.json (its last
file: the publish comes next) or has become the run's folder (the publish's first step),
then after DELAY_US microseconds (a busy wait: a sleep's
wake-up is coarser than a publish of a few files) sends SIGKILL. DELAY_US < 0: no kill.
Prints the exit status as the shell gives it (137 killed), the run's pid and the
microseconds from summary.json seen to the exit."""
import os
import signal
import subprocess
import sys
import time

sim, scen, out, delay = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
p = subprocess.Popen([sim, scen, "--out", out], stdout=subprocess.DEVNULL,
                     stderr=subprocess.DEVNULL)
prefix = ".run.relcol-%d." % p.pid
stage = None
while p.poll() is None:
    try:
        names = os.listdir(out)
    except FileNotFoundError:
        continue
    if stage is None:
        stage = next((n for n in names if n.startswith(prefix)), None)
    # (the publish's first step renames the staging folder .relcol-run.XXXXXX, its last
    # 6 characters kept: a poll that missed summary.json there sees that)
    if stage and (".relcol-run." + stage[-6:] in names or
                  os.path.exists(os.path.join(out, stage, "summary.json"))):
        break
t0 = time.perf_counter()
if delay >= 0:
    while time.perf_counter() - t0 < delay * 1e-6:
        pass
    if p.poll() is None:
        p.send_signal(signal.SIGKILL)
rc = p.wait()
t1 = time.perf_counter()
print(128 - rc if rc < 0 else rc, p.pid, int((t1 - t0) * 1e6))
