"""relcol: relativistic hard-ball collisions with the speed of light c as a parameter.

A Python package over librelcol (the C library): numpy arrays in, numpy arrays out, the
library's own numbers (the same bits the C apps print), and every library failure a
RelcolError carrying the library's message. c = inf (math.inf) is the classical limit.

    collide(m0, p0, m1, p1, n, c=, eps=, law=)   collisions of N pairs at once
    toi(x0, r0, m0, p0, x1, r1, m1, p1, c=, frame=)   time of first contact
    soft_collide(m, p, x, r, c=, eps=, stiffness=)    the soft-sphere reference
    Sim(scenario)                                 the event-driven engine
    Sim(scenario, gravity={"g":, "coupling":})    ... in a uniform field; sim.profile()
    read_profiles(path), couplings()              relcol-sim's profiles.csv; the field's couplings
    read_summary, read_snapshot(s), read_h5md, read_run   relcol-sim's outputs
    gas_init(...), Gas1D(...)                     gases
    laws(), frames(), steppers()                  the library's tables
    momentum(m, v, c), velocity(m, p, c), ...     kinematics
"""
from ._relcol import ffi as _ffi, lib as _lib
from .errors import RelcolError, strerror
from .kinematics import gamma, inv_c2, kinetic_energy, mass_rel, momentum, velocity
from .laws import Collision, Law, collide, laws
from .toi import Contact, Frame, frames, toi
from .soft import SoftResult, soft_collide, steppers
from .errors import ScenarioError
from .scenario import load_scenario
from .sim import Sim
from .outputs import read_h5md, read_run, read_snapshot, read_snapshots, read_summary
from .gas import Gas1D, gas_init
from .field import couplings, read_profiles

__version__ = _ffi.string(_lib.rc_version()).decode()

__all__ = ["RelcolError", "strerror", "gamma", "inv_c2", "kinetic_energy", "mass_rel",
           "momentum", "velocity", "Collision", "Law", "collide", "laws", "Contact",
           "Frame", "frames", "toi", "SoftResult", "soft_collide", "steppers", "Sim",
           "load_scenario", "ScenarioError", "Gas1D", "gas_init", "read_summary", "read_snapshot",
           "read_snapshots", "read_h5md", "read_run", "couplings", "read_profiles", "__version__"]
