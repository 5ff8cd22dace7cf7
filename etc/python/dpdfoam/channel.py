"""Channel flows between two walls: the no-slip Poiseuille profile, kT against the local shear rate,
the slip of the two walls, and fitSlipLength's parabola for jackknife errors over super-blocks."""
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


def walls_mean_slip(sweep):
    """Per run of a sweep, the slip length of the two walls' mean and its standard error (a fluctuation
    of the channel's mean velocity moves the two walls' slip in opposite directions and cancels here)."""
    b = 0.5 * (np.asarray(sweep["slipLength_0"]) + np.asarray(sweep["slipLength_1"]))
    return b, 0.5 * np.hypot(sweep["slipLengthError_0"], sweep["slipLengthError_1"])


def poiseuille_fit(z, u, sigma, walls, exclude, g):
    """nu and the slip lengths (lower, upper) of fitSlipLength's weighted parabola (mode poiseuille) fitted
    to the bins at least `exclude` from the walls (slip = u / du/dn at the wall). On the run's profile it
    gives fit.dat's numbers to rounding; it serves only the leave-one-out fits below, which fitSlipLength lacks."""
    lo, hi = walls
    sel = (z >= lo + exclude) & (z <= hi - exclude) & np.isfinite(u) & (sigma > 0)
    c2, c1, c0 = np.polyfit(z[sel], u[sel], 2, w=1.0 / sigma[sel])
    value = lambda x: c0 + c1 * x + c2 * x * x  # noqa: E731
    slope = lambda x: c1 + 2.0 * c2 * x  # noqa: E731
    return np.array([-g / (2.0 * c2), value(lo) / slope(lo), -value(hi) / slope(hi)])


def leave_one_out_poiseuille(z, count, sum_u, sigma, walls, exclude, g):
    """(nu, slip lower, slip upper) of the profile of every super-block but one, each left out in turn
    (count, sum_u: particle-samples and sums of u per super-block and bin), refitted with the run's bin
    errors sigma: an (m, 3) array, for stats.jackknife_error."""
    total_c, total_s = count.sum(axis=0), sum_u.sum(axis=0)
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.array([poiseuille_fit(z, (total_s - sum_u[k]) / (total_c - count[k]), sigma, walls, exclude, g)
                         for k in range(len(count))])


def fit_weights(table):
    """fitSlipLength's bin errors for a refit: the table's uxErr, an empty bin (error 0) weightless."""
    return np.where(table["uxErr"] > 0, table["uxErr"], np.inf)
