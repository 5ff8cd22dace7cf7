#!/usr/bin/env python3
"""poiseuilleFVM: picture, results table and checks of the DPD channel against its simpleFoam twins.

Checks (non-zero exit status when one fails):
 1. simpleFoam (no-slip twin) reproduces the analytic parabola u = g (z - z_lo)(z_hi - z) / (2 nu) to
    solver precision. On a uniform mesh the finite-volume solution of this problem is exactly the
    parabola shifted by g h^2 / (8 nu) at the cell centres (the half-cell wall gradient (U_P - 0)/(h/2)
    is the one inexact term; the wall flux is fixed at g d / 2 by the force balance, so the shift is
    the same in every cell), so the cell values must equal analytic + g h^2 / (8 nu) to the solver's
    tolerance (residualControl 1e-12: 1e-8 of the centre velocity is ample).
 2. The DPD profile against the twin with the measured nu and slip lengths (compareFVM, field L2):
    full run: L2 < 3 %.
    -test: the short run's profile is noisy, so L2 is held to the noise: when the continuum is the
    truth, E[L2^2] = noiseL2^2 (noiseL2 = sqrt(sum err^2 / sum u^2), the bins' standard errors), less the
    3 parameters the fit took from the same bins; L2^2 / noiseL2^2 scatters like chi^2/N with
    relative standard deviation sqrt(2 / N). The bound noiseL2 * sqrt(1 + 4 sqrt(2 / N)) is 4 standard
    deviations above that, plus the discretisation (h/d)^2 of the continuum.
"""
import math
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def latest(directory):
    times = [d for d in os.listdir(directory) if re.fullmatch(r"[0-9.eE+-]+", d) and float(d) > 0]
    return max(times, key=float)


def read_dictionary(path):
    """Top-level 'keyword value;' entries (numbers and lists of numbers) of a small dictionary."""
    values = {}
    with open(path) as f:
        for line in f:
            m = re.match(r"^(\w+)\s+(.*);\s*$", line)
            if not m:
                continue
            text = m.group(2).strip()
            if text.startswith("("):
                try:
                    values[m.group(1)] = [float(x) for x in text.strip("()").split()]
                except ValueError:
                    values[m.group(1)] = text
            else:
                try:
                    values[m.group(1)] = float(text)
                except ValueError:
                    values[m.group(1)] = text.strip('"')
    return values


def read_vector_field(path):
    """internalField of an ascii volVectorField (nonuniform List<vector>)."""
    text = open(path).read()
    body = text[text.index("internalField"):]
    n = int(re.search(r"List<vector>\s*(\d+)", body).group(1))
    start = body.index("(", body.index("List<vector>")) + 1
    numbers = re.findall(r"[-+0-9.eE]+", body[start:].replace("(", " ").replace(")", " "))
    return np.array(numbers[: 3 * n], dtype=float).reshape(n, 3)


def main():
    test = "-test" in sys.argv[1:]
    t = latest("postProcessing/compareFVM")
    cmp = read_dictionary(f"postProcessing/compareFVM/{t}/compare.dat")
    prof = np.loadtxt(f"postProcessing/compareFVM/{t}/profiles.dat")
    fit = read_dictionary(f"postProcessing/fitSlipLength/{latest('postProcessing/fitSlipLength')}/fit.dat")
    rec = read_dictionary("simpleFoamNoSlip/constant/dpdCase")
    z_lo, z_hi = rec["meshMin"][2], rec["meshMax"][2]
    d = z_hi - z_lo
    g, nu = rec["g"][0], rec["nu"]
    h = d / rec["cells"][2]

    # 1. simpleFoam against the analytic parabola (no-slip twin).
    ft = latest("simpleFoamNoSlip")
    C = read_vector_field(f"simpleFoamNoSlip/{ft}/C")
    U = read_vector_field(f"simpleFoamNoSlip/{ft}/U")
    z = C[:, 2]
    analytic = g * (z - z_lo) * (z_hi - z) / (2 * nu)
    u_max = g * d * d / (8 * nu)
    shift = g * h * h / (8 * nu)
    solver_error = np.max(np.abs(U[:, 0] - (analytic + shift))) / u_max
    discretisation = np.max(np.abs(U[:, 0] - analytic)) / u_max

    # The plain continuum prediction (no slip) at the DPD bins, reported: the slip the DPD walls show.
    zb, ud, ue, uf = prof[:, 0], prof[:, 1], prof[:, 2], prof[:, 3]
    inside = np.isfinite(uf)
    order = np.argsort(z)
    u_noslip = np.interp(zb[inside], z[order], U[order, 0])
    L2_noslip = math.sqrt(np.sum((ud[inside] - u_noslip) ** 2) / np.sum(u_noslip ** 2))

    # 2. DPD against the twin with the measured nu and slip.
    L2, noise = cmp["L2"], cmp["noiseL2"]
    n = int(cmp["points"])
    if test:
        tolerance = noise * math.sqrt(1 + 4 * math.sqrt(2 / n)) + (h / d) ** 2
        dpd_check = (f"DPD vs simpleFoam (measured nu, slip): L2 <= {tolerance:.4f} (4 sigma of the DPD noise)",
                     L2 <= tolerance, f"L2 = {L2:.4f}, noise L2 = {noise:.4f}, {n} bins")
    else:
        dpd_check = ("DPD vs simpleFoam (measured nu, slip): L2 < 3 %", L2 < 0.03, f"L2 = {L2:.4f}")
    checks = [
        ("simpleFoam = analytic + g h^2/(8 nu) to solver precision (< 1e-8 of u_max)", solver_error < 1e-8,
         f"{solver_error:.2e}"),
        dpd_check,
    ]

    with open("results.dat", "w") as f:
        f.write(f"# poiseuilleFVM at DPD time {t}, simpleFoam time {ft} (no slip)\n")
        f.write(f"nu                {nu:.5f} +- {fit.get('nuError', 0.0):.5f}  (fitSlipLength)\n")
        f.write(f"slipLength        {fit['slipLength'][0]:+.4f} {fit['slipLength'][1]:+.4f}\n")
        f.write(f"simpleFoamSolver  {solver_error:.3e}  (max |U - analytic - g h^2/8nu| / u_max)\n")
        f.write(f"discretisation    {discretisation:.3e}  (max |U - analytic| / u_max; (h/d)^2 = {(h / d) ** 2:.3e})\n")
        f.write(f"L2                {L2:.5f}\nLinf              {cmp['Linf']:.5f}\nnoiseL2           {noise:.5f}\n")
        f.write(f"meanVelocityRatio {cmp['meanVelocityRatio']:.5f}\n")
        f.write(f"L2NoSlip          {L2_noslip:.5f}  (DPD against the no-slip twin; reported)\n")
        for name, ok, value in checks:
            f.write(f"check  {'PASS' if ok else 'FAIL'}  {name}: {value}\n")
    print(open("results.dat").read(), end="")

    fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
    zz = np.linspace(z_lo, z_hi, 200)
    ax[0].errorbar(zb, ud, yerr=ue, fmt="o", ms=3, label="DPD (profileBins)")
    ax[0].plot(zb, uf, "r-", lw=1.5, label=f"simpleFoam, nu = {nu:.3f}, fitted slip")
    ax[0].plot(z, U[:, 0], "g--", lw=1, label="simpleFoam, no slip")
    ax[0].plot(zz, g * (zz - z_lo) * (z_hi - zz) / (2 * nu), "k:", lw=1, label="analytic, no slip")
    ax[0].set_xlabel("z")
    ax[0].set_ylabel("u_x")
    ax[0].legend(fontsize=8)
    ax[0].set_title(f"channel d = {d:g}: DPD and simpleFoam")
    ax[1].errorbar(zb, ud - uf, yerr=ue, fmt="o", ms=3)
    ax[1].axhline(0, color="k", lw=0.8)
    ax[1].set_xlabel("z")
    ax[1].set_ylabel("u_DPD - u_simpleFoam")
    ax[1].set_title(f"L2 = {L2:.4f} (noise {noise:.4f}), Linf = {cmp['Linf']:.4f}")
    fig.tight_layout()
    fig.savefig("poiseuilleFVM.png", dpi=120)
    return 0 if all(ok for _, ok, _ in checks) else 1


if __name__ == "__main__":
    sys.exit(main())
