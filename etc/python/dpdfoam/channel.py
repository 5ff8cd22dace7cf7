"""Channel flows between two walls: the no-slip Poiseuille profile, kT against the local shear rate,
and the slip of the two walls."""
import numpy as np

from .io import body_force, latest_fit, latest_profile


def poiseuille_velocity(z, low, high, g, nu):
    """The no-slip Poiseuille profile u = g (z - low)(high - z) / (2 nu) between walls at low and high."""
    return g * (z - low) * (high - z) / (2 * nu)


def kT_against_shear(periodic, g, nu):
    """kT against the local shear rate in the periodic box without walls (a tutorial's viscosity/ case).

    DPD heats a sheared fluid: the work eta shear^2 is taken out by the pair thermostat only once the
    fluid is warmer than the set kT, and the thermostat relaxes fast enough (a rate of a few per unit
    time against heat diffusion over about one cutoff) for kT to follow the local shear rate. The
    periodic reverse-Poiseuille box covers the same shear rates as the channel (0 at its velocity
    extremes to g L / (4 nu) at the half boundaries, as 0 at the centre to g d / (2 nu) at the walls)
    with no wall to take heat away, so it measures kT(shear) for this fluid. Returns (shear, kT)
    sorted by shear, averaged over the four quarter-periods.
    """
    z, kT = periodic["z"], periodic["kT"]
    lo = z[0] - 0.5 * (z[1] - z[0])
    length = (z[1] - z[0]) * len(z)
    # Distance to the nearest velocity extreme, at a quarter and three quarters of the box.
    x = np.minimum(np.abs(z - (lo + 0.25 * length)), np.abs(z - (lo + 0.75 * length)))
    edges = np.linspace(0.0, 0.25 * length, 21)
    which = np.clip(np.digitize(x, edges) - 1, 0, len(edges) - 2)
    centres = 0.5 * (edges[1:] + edges[:-1])
    means = np.array([np.mean(kT[which == k]) for k in range(len(centres))])
    return g * centres / nu, means


def no_wall_reference(case="viscosity", profile="viscosityProfile"):
    """The fluid without walls (a tutorial's periodic reverse-Poiseuille box): nu and its error
    (fitSlipLength), its profile table, and kT against the shear rate there (kT_against_shear)."""
    fit, periodic = latest_fit(case), latest_profile(case, profile)
    return {"nu": fit["nu"], "nuError": fit["nuError"], "table": periodic,
            "kT_of_shear": kT_against_shear(periodic, body_force(case), fit["nu"])}


def walls_mean_slip(sweep, name="slipLength"):
    """Per run of a sweep, the slip length of the two walls' mean and its standard error (a fluctuation
    of the channel's mean velocity moves the two walls' slip in opposite directions and cancels here).
    name: the columns' stem (<name>_0, <name>Error_0, ...; slipTensor's slipParallel, slipPerpendicular)."""
    b = 0.5 * (np.asarray(sweep[name + "_0"]) + np.asarray(sweep[name + "_1"]))
    return b, 0.5 * np.hypot(sweep[name + "Error_0"], sweep[name + "Error_1"])
