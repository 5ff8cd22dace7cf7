#!/usr/bin/env python3
"""Poiseuille tutorial, continuum side: picture, table and checks of the DPD channel against its
simpleFoam twin (makeFoamCase: nu measured without walls in viscosity/, no slip).

Checks (non-zero exit status when one fails):
 1. simpleFoam reproduces the analytic parabola u = g (z - z_lo)(z_hi - z) / (2 nu) to
    solver precision: on a uniform mesh its cell values are exactly the parabola shifted by
    g h^2 / (8 nu) (dpdfoam.lattice_wall.foam_twin says why), so they must equal analytic +
    g h^2 / (8 nu) to the solver's tolerance (residualControl 1e-12: 1e-8 of the centre velocity is ample).
 2. The DPD profile against the twin (compareFVM, relative L2 over the bins inside the fluid) < 3 %,
    in both modes. Nothing in the twin is fitted to the channel: its nu comes from the periodic box
    without walls, its walls do not slip. In the test (d = 10, g = 0.08) the profile's own noise
    is ~0.5 % (noiseL2), so the bound is decisive there too.
"""
import sys

from dpdfoam.checks import Checks, write_results
from dpdfoam.io import latest_fit
from dpdfoam.lattice_wall import draw_twin, foam_twin

# The profile's own noise (compareFVM's noiseL2) first below a budget, so that the 3 % bound decides:
# measured 0.0036 in the test (d = 10), less at full size.
NOISE_BUDGET = 0.01


def main():
    twin, fit = foam_twin(), latest_fit()
    t, cmp, d, h, nu = twin["time"], twin["compare"], twin["d"], twin["h"], twin["nu"]
    solver_error, discretisation = twin["solverError"], twin["discretisation"]
    L2, noise = cmp["L2"], cmp["noiseL2"]
    checks = Checks()
    # 1. simpleFoam against the analytic parabola; 2. DPD against the twin.
    checks.add("simpleFoam = analytic + g h^2/(8 nu) to solver precision (< 1e-8 of u_max)", solver_error < 1e-8,
               f"{solver_error:.2e}")
    checks.bounded(f"DPD vs simpleFoam (nu without walls, no slip): L2 < 3 % (its noise L2 below {NOISE_BUDGET:g})",
                   L2, noise, NOISE_BUDGET, None, 0.03, f"L2 = {L2:.4f}, noise L2 = {noise:.4f}, {int(cmp['points'])} bins")
    write_results("resultsFVM.dat", [
        f"# DPD channel at time {t} against simpleFoam (time {twin['foamTime']}): nu without walls, no slip",
        f"nu                {nu:.5f}  (viscosity/, no walls)",
        f"slipLength        {fit['slipLength'][0]:+.4f} {fit['slipLength'][1]:+.4f}  (fitSlipLength, for reference)",
        f"simpleFoamSolver  {solver_error:.3e}  (max |U - analytic - g h^2/8nu| / u_max)",
        f"discretisation    {discretisation:.3e}  (max |U - analytic| / u_max; (h/d)^2 = {(h / d) ** 2:.3e})",
        f"L2                {L2:.5f}\nLinf              {cmp['Linf']:.5f}\nnoiseL2           {noise:.5f}",
        f"meanVelocityRatio {cmp['meanVelocityRatio']:.5f}"], checks)
    draw_twin(twin)  # compareFVM.png
    print("Written compareFVM.png and resultsFVM.dat")
    return checks.status()


if __name__ == "__main__":
    sys.exit(main())
