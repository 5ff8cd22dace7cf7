"""dpdfoam.channel against analytic channel flows.

The no-slip Poiseuille profile vanishes at both walls, peaks at g d^2 / (8 nu) midway, satisfies
nu u'' = -g and carries the flux g d^3 / (12 nu) (Simpson's rule, exact for a parabola). kT against the
shear rate is read back from a periodic reverse-Poiseuille box whose kT was set to a known function of
the local shear rate, the shear computed here from the analytic velocity profile. The viscous heating's
weight integral C = int w_D d^3r is integrated numerically (4 pi rc^3 / 30) before the balance
eta shear^2 = rho^2 gamma C (kT - kT0) is checked. The walls' mean slip and its error, the fluid layer
at each wall (count-weighted kT, its error, the density's peak and the bulk) and the walls' event rates
per unit time and area of the log's reports come out as computed by hand.
"""
import math
import os
import unittest

import numpy as np

from dpdfoam.channel import (kT_against_shear, near_wall_layer, no_wall_reference, poiseuille_velocity, viscous_heating,
                             wall_event_rates, walls_mean_slip)
from dpdtest_support import fake_dictionary, Temporary, write_fit, write_table, write_text


class Poiseuille(unittest.TestCase):
    low, high, g, nu = -3.0, 5.0, 0.02, 0.3

    def test_walls_and_centre(self):
        u = lambda z: poiseuille_velocity(z, self.low, self.high, self.g, self.nu)  # noqa: E731
        self.assertEqual(u(self.low), 0.0)
        self.assertEqual(u(self.high), 0.0)
        d = self.high - self.low
        self.assertAlmostEqual(u(0.5 * (self.low + self.high)), self.g * d * d / (8 * self.nu), places=14)

    def test_momentum_balance_and_flux(self):
        z = np.linspace(self.low, self.high, 401)
        u = poiseuille_velocity(z, self.low, self.high, self.g, self.nu)
        h = z[1] - z[0]
        second = (u[2:] - 2 * u[1:-1] + u[:-2]) / h ** 2  # exact for a parabola
        np.testing.assert_allclose(self.nu * second, -self.g, rtol=1e-8)
        flux = h / 3 * (u[0] + u[-1] + 4 * u[1:-1:2].sum() + 2 * u[2:-1:2].sum())
        self.assertAlmostEqual(flux / (self.g * (self.high - self.low) ** 3 / (12 * self.nu)), 1.0, places=12)


class KTAgainstShear(unittest.TestCase):
    def test_reverse_poiseuille_box(self):
        # Periodic box of length 40, force +g on the lower half and -g on the upper: u = g z (L/2 - z) /
        # (2 nu) on [0, L/2] and its mirror, shear |du/dz| = g |z - L/4| / nu (lower) and g |z - 3L/4| / nu.
        # kT is set to 1 + 0.5 shear; each of the 20 shear bins holds points symmetric about its centre.
        g, nu, length, dz = 0.05, 0.25, 40.0, 0.05
        z = dz * (np.arange(int(length / dz)) + 0.5)
        lower = z < length / 2
        u = np.where(lower, g * z * (length / 2 - z), -g * (z - length / 2) * (length - z)) / (2 * nu)
        shear = np.abs(np.where(lower, g * (length / 2 - 2 * z), -g * (3 * length / 2 - 2 * z)) / (2 * nu))
        smooth = np.abs(z - length / 2) > dz  # central differences are exact for the parabolas, not across the force's switch
        smooth[[0, -1]] = False
        np.testing.assert_allclose(shear[smooth], np.abs(np.gradient(u, dz))[smooth], atol=1e-12)  # the derivative, checked
        rates, kT = kT_against_shear({"z": z, "kT": 1.0 + 0.5 * shear}, g, nu)
        self.assertEqual(len(rates), 20)
        np.testing.assert_allclose(rates, g / nu * (np.arange(20) + 0.5) * 0.5, rtol=1e-12)
        np.testing.assert_allclose(kT, 1.0 + 0.5 * rates, rtol=1e-12)
        self.assertAlmostEqual(rates[-1] + 0.5 * (rates[1] - rates[0]), g * length / (4 * nu), places=12)


class ViscousHeating(unittest.TestCase):
    def test_weight_integral_and_balance(self):
        for cutoff in (1.0, 1.5):
            r = np.linspace(0.0, cutoff, 2001)
            f = 4 * math.pi * r ** 2 * (1 - r / cutoff) ** 2
            h = r[1] - r[0]
            c = h / 3 * (f[0] + f[-1] + 4 * f[1:-1:2].sum() + 2 * f[2:-1:2].sum())
            self.assertAlmostEqual(c / (4 * math.pi * cutoff ** 3 / 30), 1.0, places=10)
            eta, shear, rho, gamma = 0.9, 0.07, 3.0, 4.5
            rise = viscous_heating(eta, shear, rho, gamma, cutoff)
            self.assertAlmostEqual(rho ** 2 * gamma * c * rise / (eta * shear ** 2), 1.0, places=9)


class WallsMeanSlip(unittest.TestCase):
    def test_mean_and_error(self):
        sweep = {"slipLength_0": np.array([1.0, 2.0]), "slipLength_1": np.array([3.0, 2.5]),
                 "slipLengthError_0": np.array([0.3, 0.1]), "slipLengthError_1": np.array([0.4, 0.1])}
        b, err = walls_mean_slip(sweep)
        np.testing.assert_allclose(b, [2.0, 2.25])
        np.testing.assert_allclose(err, [0.25, 0.5 * math.sqrt(0.02)])
        sweep = {"slipParallel_0": [1.0], "slipParallel_1": [np.nan], "slipParallelError_0": [0.1], "slipParallelError_1": [0.1]}
        b, err = walls_mean_slip(sweep, "slipParallel")
        self.assertTrue(np.isnan(b[0]))


def wall_layer_table():
    """Bins of 0.25 from -1 to 11, walls at 0 and 10 (no fluid behind them); kT 1.5 within one cutoff of
    the fluid's edges (one bin there 2.0 with twice the samples), 1 elsewhere; a density peak of 3.6."""
    z = -1.0 + 0.25 * (np.arange(48) + 0.5)
    fluid = (z > 0) & (z < 10)
    density = np.where(fluid, 3.0, 0.0)
    density[np.flatnonzero(fluid)[1]] = 3.6
    count = 100.0 * density
    kT = np.where(fluid, 1.0, 0.0)
    layer = fluid & ((z < 1.0) | (z > 9.0))
    kT[layer] = 1.5
    edge = np.flatnonzero(fluid)[0]
    kT[edge], count[edge] = 2.0, 2 * count[edge]
    return {"z": z, "density": density, "count": count, "kT": kT, "kTErr": np.full(48, 0.02)}, layer, fluid


class NearWallLayer(unittest.TestCase):
    def test_layer(self):
        table, layer, _ = wall_layer_table()
        self.assertEqual(layer.sum(), 8)
        kT, kT_err, peak, bulk_density = near_wall_layer(table, np.abs(table["z"] - 5.0) < 2.5)
        # Layer: 8 bins; one at 2.0 with 600 samples, one at 1.5 with 360 (the peak), six at 1.5 with 300.
        self.assertAlmostEqual(kT, (600 * 2.0 + 360 * 1.5 + 6 * 300 * 1.5) / (600 + 360 + 1800), places=13)
        self.assertAlmostEqual(kT_err, 0.02 * math.sqrt(600 ** 2 + 360 ** 2 + 6 * 300 ** 2) / 2760, places=14)
        self.assertEqual(peak, 3.6)
        self.assertEqual(bulk_density, 3.0)


class CaseReaders(Temporary):
    def test_wall_event_rates(self):
        case = os.path.join(self.tmp, "case")
        reports = "".join(f"Time = {t}  (step {100 * t})\n    kT = 1   momentum = (0 0 0)   meanVelocity = (0 0 0)\n"
                          f"    walls since last report: lower returned 40 crossed 2; upper returned 60 crossed 0;"
                          f" left inside after a step 0; inside walls now 0\n\n" for t in range(1, 11))
        write_text(os.path.join(case, "log.dpdFoamLike"), reports)
        builder = os.path.join(case, "system", "blockFrozenWallDict")
        with fake_dictionary(self.tmp, {(builder, "box/min"): "(-2 -1.5 -6)", (builder, "box/max"): "(2 1.5 6)"}):
            returned, crossed = wall_event_rates(case, "blockFrozenWallDict", 4.0)
        # Reports at 5..10 count: 6 x 100 returned, 6 x 2 crossed, over 6 time units and 2 x (4 x 3) area.
        self.assertAlmostEqual(returned, 600 / (6 * 24), places=14)
        self.assertAlmostEqual(crossed, 12 / (6 * 24), places=14)

    def test_no_wall_reference(self):
        case = os.path.join(self.tmp, "viscosity")
        write_fit(case, {"nu": 0.31, "nuError": 0.004})
        z = 0.25 * (np.arange(160) + 0.5)
        write_table(os.path.join(case, "postProcessing", "profileBins", "100", "viscosityProfile.dat"),
                    {"z": z, "kT": np.ones(160), "ux": np.zeros(160)})
        with fake_dictionary(self.tmp, {(os.path.join(case, "constant", "dpdProperties"), "bodyForce/value"): "(0.04 0 0)"}):
            ref = no_wall_reference(case)
        self.assertEqual((ref["nu"], ref["nuError"]), (0.31, 0.004))
        np.testing.assert_array_equal(ref["table"]["z"], z)
        rates, kT = ref["kT_of_shear"]
        np.testing.assert_allclose(rates, 0.04 / 0.31 * (np.arange(20) + 0.5) * 0.5, rtol=1e-12)
        np.testing.assert_allclose(kT, 1.0)


if __name__ == "__main__":
    unittest.main()
