"""Channel flows between two walls: the no-slip Poiseuille profile, kT against the local shear rate,
the slip of the two walls, and the particles the walls turn round or let through."""
import math

import numpy as np

from .io import body_force, dictionary_value, latest_fit, latest_profile, vector, wall_events


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


def viscous_heating(eta, shear, rho, gamma, cutoff):
    """The rise of kT from DPD's own viscous heating at a uniform shear rate: shear heats the fluid at
    eta shear^2 per volume, the pair thermostat takes heat out at gamma rho^2 C (kT - kT0) per volume,
    C = int w_D d^3r = 4 pi rc^3 / 30 (the standard weight); in balance kT - kT0 = eta shear^2 /
    (rho^2 gamma C)."""
    return eta * shear * shear / (rho * rho * gamma * 4.0 * math.pi * cutoff ** 3 / 30.0)


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


def near_wall_layer(table, bulk):
    """A channel's fluid next to its walls, from a profileBins table: kT over the first cutoff of fluid at
    each wall (count-weighted) and its error, the density's peak, and the bulk's density (the mean over
    the bins `bulk` selects)."""
    z, rho = table["z"], table["density"]
    bulk_density = float(np.mean(rho[bulk]))
    fluid = rho > 0.05 * bulk_density
    layer = fluid & ((z < z[fluid].min() + 1.0) | (z > z[fluid].max() - 1.0))
    w = table["count"][layer]
    kT = float(np.sum(w * table["kT"][layer]) / np.sum(w))
    kT_err = float(np.sqrt(np.sum((w * table["kTErr"][layer]) ** 2)) / np.sum(w))
    return kT, kT_err, float(rho.max()), bulk_density


def wall_event_rates(case, builder, start):
    """(returned, crossed) of io.wall_events after time start, per unit time and area of the builder box's two x-y faces."""
    box = [vector(dictionary_value(f"{case}/system/{builder}", f"box/{k}")) for k in ("min", "max")]
    area = 2.0 * (box[1][0] - box[0][0]) * (box[1][1] - box[0][1])
    returned, crossed, span = wall_events(f"{case}/log.dpdFoamLike", start)
    return returned / (span * area), crossed / (span * area)
