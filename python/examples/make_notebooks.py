"""make_notebooks.py -- writes the example notebooks (elastic_collisions, sweep_c, h5md)
beside itself from the cells below, so that they are reviewed as code; run it with
/usr/bin/python3 (nbformat) after editing a cell. The suite executes the .ipynb files
(python/tests/test_notebooks.py)."""
import os

import nbformat as nbf
def nb(cells):
    n = nbf.v4.new_notebook()
    n.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
    for kind, src in cells:
        n.cells.append(nbf.v4.new_markdown_cell(src.strip()) if kind == "md" else nbf.v4.new_code_cell(src.strip()))
    return n

elastic = [
("md", r"""
# Elastic collisions with relcol: seed 004 redone, at c = ∞ and at finite c

Seed 004's notebook moves six balls in a box with a fixed time step, tests for overlaps
after each step and pushes overlapping balls apart: energy is kept only to the step's
accuracy. relcol's engine is event-driven: it finds each contact's exact time and
resolves it there, so momentum (balls plus the walls' impulse) and energy are conserved
to round-off, at any speed of light $c$.

Classically (c = ∞) an elastic contact along the normal $\hat n$ exchanges the normal
velocity components by the 1-D formulas
$v_{1n}' = \frac{(m_1-m_2)v_{1n} + 2m_2v_{2n}}{m_1+m_2}$, tangential ones kept. At finite
$c$ the ball is its rest mass $m$ and momentum $\vec p$, with energy
$E = \sqrt{m^2c^4 + p^2c^2}$; the zmf law conserves $\sum \vec p$ and $\sum E$ and
reflects the normal momentum in the pair's zero-momentum frame.
"""),
("code", r"""
import math
import numpy as np
import matplotlib
import matplotlib.pyplot as plt
from matplotlib import animation
from matplotlib.patches import Circle
from IPython.display import HTML
import relcol
"""),
("md", "## The six balls of seed 004, classically"),
("code", r"""
# (x, y, vx, vy, mass, radius) as in seed 004
config = [(2.0, 5.0, 3.0, 0.5, 2.0, 0.4), (8.0, 5.0, -2.0, 0.3, 1.5, 0.35),
          (5.0, 2.0, 0.5, 2.5, 1.0, 0.3), (5.0, 8.0, -0.5, -2.0, 1.0, 0.3),
          (3.0, 3.0, 1.5, 1.5, 0.8, 0.25), (7.0, 7.0, -1.0, -1.0, 1.2, 0.32)]
colors = ["red", "blue", "green", "orange", "purple", "cyan"]
balls = [{"x": [x, y], "v": [vx, vy], "m": m, "r": r} for x, y, vx, vy, m, r in config]

def run(c, t_end=15.0, dt=0.02):
    sim = relcol.Sim(dim=2, box=[10, 10], c=c, balls=balls)
    rec = {"t": [], "x": [], "energy": [], "P": []}
    for s in sim.steps(dt, t_end):
        d = s.diagnostics()
        rec["t"].append(s.time)
        rec["x"].append(s.positions)
        rec["energy"].append(d["energy"])
        # momentum of the balls plus what the walls took: conserved
        rec["P"].append(d["momentum"] + d["wall_impulse"])
    return sim, {k: np.array(v) for k, v in rec.items()}

sim, rec = run(math.inf)
d = sim.diagnostics()
print(sim, "|", d["collisions"], "contacts")
print("energy error %.2e, momentum error %.2e" % (d["energy_error"], d["momentum_error"]))
# conservation to round-off: relative 1e-13 over a few hundred contacts
assert abs(d["energy_error"]) < 1e-13 and d["momentum_error"] < 1e-13
assert d["collisions"] > 20
"""),
("code", r"""
def conservation_figure(rec, title):
    fig, ax = plt.subplots(1, 3, figsize=(14, 4))
    for i, col in enumerate(colors):
        ax[0].plot(rec["x"][:, i, 0], rec["x"][:, i, 1], color=col, lw=0.6)
    ax[0].set(xlim=(0, 10), ylim=(0, 10), aspect="equal", xlabel="x", ylabel="y",
              title="trajectories (" + title + ")")
    e0 = rec["energy"][0]
    ax[1].plot(rec["t"], rec["energy"] / e0 - 1)
    ax[1].set(xlabel="t", ylabel="E / E(0) - 1", title="energy (kinetic + heat)")
    P0 = rec["P"][0]
    scale = np.abs(rec["P"]).max()
    for k, name in enumerate("xy"):
        ax[2].plot(rec["t"], (rec["P"][:, k] - P0[k]) / scale, label="$P_%s$" % name)
    ax[2].set(xlabel="t", ylabel="(P - P(0)) / max |P|",
              title="momentum of balls + wall impulse")
    ax[2].legend()
    fig.tight_layout()
    return fig

conservation_figure(rec, "c = inf");
"""),
("md", "An animation of the box (the frames the run was sampled at):"),
("code", r"""
def animate(rec, radii, every=3):
    fig, ax = plt.subplots(figsize=(4, 4))
    ax.set(xlim=(0, 10), ylim=(0, 10), aspect="equal", xlabel="x", ylabel="y")
    discs = [ax.add_patch(Circle(rec["x"][0, i], radii[i], color=col))
             for i, col in enumerate(colors)]
    label = ax.text(0.3, 9.3, "")
    def frame(k):
        for i, disc in enumerate(discs):
            disc.center = rec["x"][k, i]
        label.set_text("t = %.2f" % rec["t"][k])
        return discs + [label]
    anim = animation.FuncAnimation(fig, frame, frames=range(0, len(rec["t"]), every),
                                   interval=60)
    plt.close(fig)
    return anim

anim = animate(rec, [b["r"] for b in balls], every=15)
HTML(anim.to_jshtml())
"""),
("md", r"""
## The same balls at finite c

At $c = 5$ the fastest ball moves at 0.6 c. The speeds now stay below $c$ however many
contacts there are, and the conserved energy is the relativistic one.
"""),
("code", r"""
sim_c, rec_c = run(5.0)
d = sim_c.diagnostics()
print(sim_c, "|", d["collisions"], "contacts")
print("energy error %.2e, momentum error %.2e" % (d["energy_error"], d["momentum_error"]))
assert abs(d["energy_error"]) < 1e-13 and d["momentum_error"] < 1e-13
assert (np.linalg.norm(sim_c.velocities, axis=1) < 5.0).all()
# the runs part ways: relativity changes the outcome of each contact
print("largest position difference to the classical run at t = 15: %.3f"
      % np.abs(sim_c.positions - sim.positions).max())
conservation_figure(rec_c, "c = 5");
"""),
("md", r"""
## Speeds in equilibrium: Maxwell–Boltzmann and Jüttner

A gas of many balls relaxes to the equilibrium distribution. In 2-D the speed
distribution is Maxwell–Boltzmann classically, $f(v)\,dv \propto v\,e^{-mv^2/2kT}dv$
with $\langle v^2\rangle = 2kT/m$, and Jüttner's at finite $c$: momenta distributed as
$e^{-E/kT}d^2p$, so $f(p)\,dp \propto p\,e^{-E(p)/kT}dp$; its mean kinetic energy is
$\langle K\rangle = kT + (kT)^2/(mc^2 + kT)$ (from $Z \propto kT\,e^{-mc^2/kT}(mc^2+kT)$),
which gives $kT$ from the gas. The χ² tests compare histograms of one snapshot.
"""),
("code", r"""
from scipy import stats

def equilibrium(c, n=1500, v_rms=0.5, seed=4, t_end=30.0):
    box, b = relcol.gas_init(2, n, 1.0, 0.2, v_rms, c=c, seed=seed)
    g = relcol.Sim(dim=2, box=box, c=c, balls=b, boundary="periodic").advance(t_end)
    print(g, "| %.0f contacts per ball" % (2 * g.diagnostics()["collisions"] / n))
    return g.state()

def chi2(counts, expect, min_count=5):
    keep = expect >= min_count
    obs, exp = counts[keep], expect[keep] * counts[keep].sum() / expect[keep].sum()
    x2 = ((obs - exp) ** 2 / exp).sum()
    return x2, stats.chi2.sf(x2, keep.sum() - 2)  # (one fitted parameter, and the norm)

def mb_pdf(v, kT, m):
    return v * m / kT * np.exp(-m * v * v / (2 * kT))

def juttner_pdf(p, kT, m, c):
    E = np.sqrt(m * m * c ** 4 + p * p * c * c)
    f = p * np.exp(-(E - m * c * c) / kT)
    return f / np.trapz(f, p)
"""),
("code", r"""
st = equilibrium(math.inf, v_rms=0.5)
m = st["m"][0]
v = np.linalg.norm(st["v"], axis=1)
kT = m * np.mean(v * v) / 2
edges = np.linspace(0, v.max(), 31)
counts, _ = np.histogram(v, edges)
mid = 0.5 * (edges[1:] + edges[:-1])
expect = mb_pdf(mid, kT, m) * np.diff(edges) * len(v)
x2, p_mb = chi2(counts, expect)
print("c = inf: Maxwell-Boltzmann chi2 = %.1f, p = %.3f" % (x2, p_mb))
assert p_mb > 0.001
plt.figure(figsize=(6, 4))
plt.hist(v, edges, density=True, alpha=0.5, label="relcol, c = inf")
vv = np.linspace(0, v.max(), 200)
plt.plot(vv, mb_pdf(vv, kT, m), "k", label="Maxwell-Boltzmann, kT = %.3g" % kT)
plt.xlabel("speed v"); plt.ylabel("probability density"); plt.legend();
"""),
("code", r"""
c = 1.0
st = equilibrium(c, v_rms=0.7)
m = st["m"][0]
p = np.linalg.norm(st["p"], axis=1)
K = relcol.kinetic_energy(st["m"], st["p"], c)
# <K> = kT + kT^2 / (m c^2 + kT): solved for kT
Kbar, mc2 = K.mean(), m * c * c
kT = (Kbar - mc2 + math.sqrt((Kbar - mc2) ** 2 + 8 * Kbar * mc2)) / 4
edges = np.linspace(0, np.quantile(p, 0.999), 31)
counts, _ = np.histogram(p, edges)
fine = np.linspace(0, edges[-1] * 3, 20001)
pdf = juttner_pdf(fine, kT, m, c)
cdf = np.concatenate([[0], np.cumsum(0.5 * (pdf[1:] + pdf[:-1]) * np.diff(fine))])
expect = np.diff(np.interp(edges, fine, cdf)) * len(p)
x2, p_j = chi2(counts, expect)
# Maxwell-Boltzmann in momentum with the same mean kinetic energy p^2/2m: kT = <p^2>/2m
kT_mb = np.mean(p * p) / (2 * m)
expect_mb = np.diff(1 - np.exp(-edges ** 2 / (2 * m * kT_mb))) * len(p)
x2_mb, p_mb = chi2(counts, expect_mb)
print("c = 1: Juttner chi2 = %.1f, p = %.3f | Maxwell-Boltzmann chi2 = %.1f, p = %.2g"
      % (x2, p_j, x2_mb, p_mb))
assert p_j > 0.001          # the relativistic gas is Juttner's ...
assert p_mb < 1e-6          # ... and not Maxwell-Boltzmann's
plt.figure(figsize=(6, 4))
plt.hist(p, edges, density=True, alpha=0.5, label="relcol, c = 1")
pp = np.linspace(0, edges[-1], 300)
plt.plot(pp, juttner_pdf(pp, kT, m, c) * np.trapz(juttner_pdf(fine, kT, m, c), fine), "k",
         label="Juttner, kT = %.3g m c^2" % (kT / mc2))
plt.plot(pp, pp / (m * kT_mb) * np.exp(-pp ** 2 / (2 * m * kT_mb)), "r--",
         label="Maxwell-Boltzmann (same <p^2>)")
plt.xlabel("momentum |p|"); plt.ylabel("probability density"); plt.legend();
"""),
]

sweep = [
("md", r"""
# The classical limit and its order: a sweep over c

relcol's laws are written once for every $c$, with $1/c^2$ as the parameter
($c = \infty$ is exactly $1/c^2 = 0$). So an outcome at finite $c$ differs from the
classical one by a series in $1/c^2$: the leading correction is of order $(v/c)^2$,
and the difference to the classical outcome falls as $c^{-2}$. This notebook collides
one pair of balls at a sweep of $c$ (all in one vectorised call of `relcol.collide`,
with `c` as an array) and fits the order: the slope of log |Δ| against log c is −2.
"""),
("code", r"""
import math
import numpy as np
import matplotlib.pyplot as plt
import relcol

# ball 0 (m = 1) at v = 0.5 against ball 1 (m = 2) at rest, an oblique normal
v0, n = np.array([0.5, 0.0]), np.array([1.0, 0.4])
c = np.logspace(0.3, 3, 40)
m0, m1 = 1.0, 2.0
p0 = np.array([relcol.momentum(m0, v0, ci) for ci in c])
out = relcol.collide(m0, p0, m1, np.zeros(2), n, c=c, eps=0.9)
cl = relcol.collide(m0, relcol.momentum(m0, v0), m1, np.zeros(2), n, eps=0.9)
v_after = np.array([relcol.velocity(m, p, ci) for m, p, ci in zip(out.m0, out.p0, c)])
delta = np.linalg.norm(v_after - cl.p0 / cl.m0, axis=1)
assert out.collided.all()
"""),
("code", r"""
# fit over the regime where (v/c)^2 is small but the difference is far above round-off
fit = (c > 10) & (delta > 1e-12)
slope, intercept = np.polyfit(np.log(c[fit]), np.log(delta[fit]), 1)
print("order of the classical limit: |delta v| ~ c^%.3f" % slope)
assert abs(slope + 2) < 0.02
plt.loglog(c, delta, "o", label="relcol.collide")
plt.loglog(c[fit], np.exp(intercept) * c[fit] ** slope, "k-",
           label="fit: slope %.3f" % slope)
plt.xlabel("c"); plt.ylabel("|v'(c) - v'(inf)| of ball 0"); plt.legend();
"""),
("md", r"""
## A whole gas: the same order in the engine

The engine's runs approach the classical run as $c \to \infty$ too. Runs of a gas at
different $c$ part ways chaotically, so the quantity here is one contact: a head-on pair
of balls at $\pm 0.5$, Lorentz-contracted along their motion in the table frame (radius
$r/\gamma$ along $x$), meets later than classically by $(1 - 1/\gamma)\,r$ per ball
over the closing speed: $O((v/c)^2)$.
"""),
("code", r"""
cs = np.logspace(1, 3, 9)
t_hit = []
for ci in cs:
    s = relcol.Sim(dim=2, box=[10, 10], c=ci, contact_frame="table",
                   balls=[{"x": [2, 5], "v": [0.5, 0], "r": 0.5},
                          {"x": [6, 5], "v": [-0.5, 0], "r": 0.5}])
    for ev in s.events(100):
        if ev.diagnostics()["collisions"]:
            break
    t_hit.append(ev.time)
t_cl = 3.0 / 1.0  # gap 3 closed at relative speed 1
dt = np.abs(np.array(t_hit) - t_cl)
slope_t = np.polyfit(np.log(cs), np.log(dt), 1)[0]
print("first contact time: |t(c) - t(inf)| ~ c^%.3f" % slope_t)
assert abs(slope_t + 2) < 0.05
"""),
]

h5md = [
("md", r"""
# Reading an H5MD run

relcol-sim writes the trajectory as H5MD (`outputs.h5md_every`), an HDF5 layout that
h5py, MDAnalysis and other tools read. This notebook runs a small gas with relcol-sim,
reads `trajectory.h5` into numpy with `relcol.read_h5md` and with plain h5py, checks that
the last frame is the run's final state, and plots the mean square displacement.
"""),
("code", r"""
import json, os, shutil, subprocess, tempfile
import numpy as np
import matplotlib.pyplot as plt
import h5py
import relcol

sim_exe = os.environ.get("RELCOL_SIM") or shutil.which("relcol-sim")
work = tempfile.mkdtemp(prefix="relcol-h5md-")
scenario = {"relcol": 1, "dim": 2, "c": 1, "seed": 7, "t_end": 20, "boundary": "periodic",
            "generate": {"kind": "gas", "n": 300, "radius": 1, "packing": 0.2, "v_rms": 0.5},
            "outputs": {"h5md_every": 0.5, "plots": False, "gif": False}}
with open(os.path.join(work, "gas.json"), "w") as f:
    json.dump(scenario, f)
subprocess.run([sim_exe, os.path.join(work, "gas.json"), "--out", os.path.join(work, "out"),
                "--no-plots"], check=True, capture_output=True)
sorted(os.listdir(os.path.join(work, "out")))
"""),
("code", r"""
run = relcol.read_h5md(os.path.join(work, "out", "trajectory.h5"))
part = run["particles"]["all"]
pos = part["position"]
print({k: (v["value"].shape if isinstance(v, dict) and "value" in v else type(v).__name__)
       for k, v in part.items()})
with h5py.File(os.path.join(work, "out", "trajectory.h5")) as f:
    assert np.array_equal(f["particles/all/position/value"][()], pos["value"])
final = json.load(open(os.path.join(work, "out", "final.json")))
assert pos["time"][-1] == final["time"]
assert np.array_equal(pos["value"][-1], [b["x"] for b in final["balls"]])
"""),
("code", r"""
# unwrapped positions: x + image L on the periodic axes
L = np.array(final["box"])
img = part["image"]["value"] if "image" in part else 0
xu = pos["value"] + img * L
msd = ((xu - xu[0]) ** 2).sum(axis=2).mean(axis=1)
t = pos["time"]
assert msd[-1] > msd[len(msd) // 2] > 0
plt.loglog(t[1:], msd[1:], "o-", label="relcol-sim, H5MD")
plt.loglog(t[1:4], msd[1] * (t[1:4] / t[1]) ** 2, "k--", label="ballistic, t^2")
plt.xlabel("t"); plt.ylabel("mean square displacement"); plt.legend();
"""),
]

for name, cells in (("elastic_collisions", elastic), ("sweep_c", sweep), ("h5md", h5md)):
    nbf.write(nb(cells), os.path.join(os.path.dirname(os.path.abspath(__file__)), name + ".ipynb"))
