#!/usr/bin/env python3
"""Striped-wall tutorial: the measured slip tensor against the project's continuum reference.

Reads the calibration (calibration/gammaL.dat: where the wall acts, each sector's gamma_L and the slip
it gives), the sweeps (slipTensor's results per run: sweepAngle/, and at full size sweepGasFraction/,
sweepLocalSlip/, sweepHeight/, sweepHalfForce/, sweepForce/, sweepPeriod/) and the fluid at rest over
the stripes (rest/); computes the reference with stripedSlip at the calibrated slips in the channel
between the hydrodynamic walls (dpdfoam.slip; the studies: dpdfoam.striped); writes results.dat and
stripedWall.png and exits non-zero when a check fails (the first fluid layer's speed and areal density at
0 and 90 degrees: information).
Every check (issue 45) first requires the standard error of its comparison (the run's, the wall
position's for slip lengths, and the calibration's: the reference recomputed at each sector's slip +-
its error) below a budget (BUDGETS: full size and test mode, each derived from measured errors), then
holds the value to a fixed bound of three budgets, never widened by the run's own error:
  - b_par and b_perp (mean of the walls, from the hydrodynamic wall) within 3 budgets of the
    reference: in the angle sweep the weighted mean of the runs that drive each, elsewhere per run
    (gas fraction, local slip, height); and b_par - b_perp of the angle sweep, which does not depend
    on where the wall acts;
  - the transverse flux ratio within 3 budgets of the reference at every angle between 0 and 90 and
    every channel height, and zero within 3 budgets at theta 0 and 90; at theta 45 the flow turns
    towards the stripes: the ratio above 3 budgets;
  - the flux linear in the force: at half the force, the flux per unit force along and across the
    stripes within 3 budgets (relative) of the flux at the standard force (twice the force is
    information: there inertia takes ~3 % of the flux, README);
  - at the period 40 (sweepPeriod/), b_par at theta 0, b_perp at theta 90 and b_par - b_perp against
    the reference at that period, as above;
  - at rest, the layer next to the walls (within zc) holds the same density and kT over the gas and
    the no-slip sectors, their difference within 3 budgets of zero.
The default (the review's fluid, a = 0) runs the angle sweep at 0 and 90 degrees only (b_par, b_perp,
their difference and zero transverse flux) and the fluid at rest; -a25 (the standard fluid, run in
a25/) every study. The test mode decides every check its runs allow (the angle sweep at 0 and 90
degrees, -a25 also 45, and the fluid at rest) with the test's budgets, but the turn at theta 45
(information: TEST_INFORMATION).
"""
import os
import sys

import numpy as np

from dpdfoam.checks import mode_budget, write_results
from dpdfoam.io import dictionary_number, read_dict, wall_planes
from dpdfoam.slip import read_slip_tensor
from dpdfoam.striped import StripedStudy, linear  # noqa: F401 (linear: tests/apps/checkBounds.sh)

TEST_MODE = "-test" in sys.argv[1:]
# The fluid: the review's (a = 0, the default) or the standard fluid's sweep (-a25, run in a25/).
FLUID = "a25" if "-a25" in sys.argv[1:] else "a0"
# The test's 800 time units cannot decide the turn at theta 45 (its budget's bound, 3 x 0.04, lies above
# the reference's 0.051): information there, every other check of the test's runs decided.
TEST_INFORMATION = ("the flow turns towards the stripes",)  # (dpdfoam.slip.turn_check's name)
# The test's slip lengths: its three-point calibration (wall +- 0.37, b0 +- 0.41 at a = 0) leaves bounds of
# 1.65-2.4, wider than b itself; their checks say so in their names (issue 45: a test mode names what it checks).
COARSE = " [test mode: coarse, its bound wider than b; the full size decides the value and the sign]" if TEST_MODE else ""
# A value within BOUND budgets of its expectation (issue 45: the bound fixed by the budget).
BOUND = 3.0
# Standard-error budgets (issue 45) per fluid, (full size, test mode). None: that study does not run.
BUDGETS = {
    # a = 25: full size from the README's runs of 2026-11-27 (the wall's position adds 0.091 to every b,
    # the calibration 0.090-0.102 to its reference, mostly the no-slip sectors' b0 +- 0.10); test from
    # its run of 2026-11-28 (800 time units; its three-point calibration: wall +- 0.30, b0 +- 0.33).
    "a25": {
        # full: run 0.021-0.029 (+) wall 0.091 (+) calibration 0.099 = 0.137; test: 0.096-0.116 (+) 0.304 (+) 0.33 = 0.46
        "b, angle sweep": (0.16, 0.55),
        # full: run 0.020-0.108 (+) wall 0.091 (+) calibration 0.090-0.102 = 0.135-0.173 (phi2, b, H and L 40)
        "b, one run": (0.19, None),
        # full: run 0.036 (+) calibration 0.005 = 0.036 (the wall cancels); test: 0.151 (+) 0.019 = 0.152
        "b_par - b_perp, angle sweep": (0.05, 0.2),
        # full: run 0.100 (+) calibration 0.033 = 0.105 (L 40)
        "b_par - b_perp, L 40": (0.13, None),
        # full: 0.007-0.011 at 22.5-67.5 degrees; test: 0.009 at 45, 0.018 and 0.036 at 90 and 0 (the
        # 3400-unit runs' 0.009-0.017 x sqrt(3000 / 600 sampled) = 0.02-0.038)
        "flux ratio, angle sweep": (0.013, 0.04),
        # full: 0.005-0.017 (phi2, b and H)
        "flux ratio, one run": (0.02, None),
        # full: 0.007 (10400 time units at 45 degrees); test: as the angle sweep's ratio
        "the flow turns": (0.01, 0.04),
        # full: 0.012 at 0, 0.009 at 90 degrees; test: 0.036 at 0, 0.018 at 90
        "zero flux": (0.015, 0.04),
        # relative: full 1.4 % along, 1.6 % across (g / 2 against g)
        "flux linear": (0.02, None),
        # full: 0.007 (1000 time units sampled); test: 0.015 (400 sampled)
        "at rest, density": (0.01, 0.02),
        # full: 0.0021; test: 0.0046
        "at rest, kT": (0.003, 0.006),
    },
    # a = 0 (theta 0 and 90 only): full size from the README's run of 2026-11-29 (13600 time units at
    # g 0.002; the wall's position adds 0.083 to every b, the calibration 0.094 to its reference);
    # test from its run of 2026-11-29 (800 time units; its three-point calibration: wall +- 0.37, b0
    # +- 0.41). Each about 1.2 x the largest measured, a share of room for the estimate's own scatter.
    "a0": {
        # full: run 0.057-0.062 (+) wall 0.083 (+) calibration 0.094 = 0.138-0.140; test: 0.29-0.34 (+) 0.37 (+) 0.40-0.41 = 0.62-0.64
        "b, angle sweep": (0.17, 0.8),
        # full: run 0.084 (+) calibration 0.008 = 0.085; test: 0.444 (+) 0.025 = 0.445
        "b_par - b_perp, angle sweep": (0.1, 0.55),
        # full: 0.0074 at 0, 0.0185 at 90 degrees; test: 0.065 at 0, 0.095 at 90
        "zero flux": (0.022, 0.12),
        # full: 0.0118, test: 0.025 (the layer within zc is half empty at a = 0: fewer particles, more
        # noise than a = 25's 0.007 over the same 1000 time units)
        "at rest, density": (0.014, 0.032),
        # full: 0.0022; test: 0.0051
        "at rest, kT": (0.003, 0.0065),
    },
}


def budget(kind, test=None, fluid=None):
    """The standard-error budget of a kind of check in this mode and fluid (or in the ones `test` and
    `fluid` name); NaN, a failed check, for a study that mode has no budget for."""
    return mode_budget(BUDGETS[fluid or FLUID], kind, TEST_MODE if test is None else test)


def main():
    cal = read_dict("calibration/gammaL.dat")
    gas_fraction = dictionary_number("constant/dpdProperties", "walls/lower/tunableSlip/stripes/gasFraction")
    study = StripedStudy(cal, wall_planes(), gas_fraction, budget, BOUND, COARSE)
    study.header(dictionary_number("constant/dpdProperties", "pairCoeffs/fluid-fluid/a"))
    s = read_slip_tensor("sweepAngle/sweep.dat", cal["offset"])
    ref = study.angle_study(s)
    study.layer_study("sweepAngle", s, ref, cal["period"])
    studies = study.sweep_studies()
    study.force_study(s, int(np.argmin(np.abs(s["theta"] - 45.0))))
    if os.path.exists("sweepPeriod/sweep.dat"):
        study.period_study(read_slip_tensor("sweepPeriod/sweep.dat", cal["offset"]))
    grid, near = study.rest_study()
    # The test's short runs (800 time units) decide every check their outputs allow with the test's
    # budgets; the turn at theta 45 is information there (TEST_INFORMATION).
    study.checks.inform(lambda name: not TEST_MODE or not name.startswith(TEST_INFORMATION))
    write_results("results.dat", study.out, study.checks)
    study.draw(s, ref, studies, grid, near)
    print("Written stripedWall.png and results.dat")
    return study.checks.status()


if __name__ == "__main__":
    sys.exit(main())
