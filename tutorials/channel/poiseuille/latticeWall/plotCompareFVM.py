#!/usr/bin/env python3
"""Poiseuille tutorial, continuum side: picture, table and checks of the DPD channel against its
simpleFoam twin (makeFoamCase: nu measured without walls in viscosity/, no slip).

Checks (non-zero exit status when one fails):
 1. simpleFoam reproduces the analytic parabola u = g (z - z_lo)(z_hi - z) / (2 nu) to
    solver precision. On a uniform mesh the finite-volume solution of this problem is exactly the
    parabola shifted by g h^2 / (8 nu) at the cell centres (the half-cell wall gradient (U_P - 0)/(h/2)
    is the one inexact term; the wall flux is fixed at g d / 2 by the force balance, so the shift is
    the same in every cell), so the cell values must equal analytic + g h^2 / (8 nu) to the solver's
    tolerance (residualControl 1e-12: 1e-8 of the centre velocity is ample).
 2. The DPD profile against the twin (compareFVM, relative L2 over the bins inside the fluid) < 3 %,
    in both modes. Nothing in the twin is fitted to the channel: its nu comes from the periodic box
    without walls, its walls do not slip. In the test (d = 10, g = 0.08) the profile's own noise
    is ~0.5 % (noiseL2), so the bound is decisive there too.
"""
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
    t = latest("postProcessing/compareFVM")
    cmp = read_dictionary(f"postProcessing/compareFVM/{t}/compare.dat")
    prof = np.loadtxt(f"postProcessing/compareFVM/{t}/profiles.dat")
    fit = read_dictionary(f"postProcessing/fitSlipLength/{latest('postProcessing/fitSlipLength')}/fit.dat")
    rec = read_dictionary("simpleFoam/constant/dpdCase")
    z_lo, z_hi = rec["meshMin"][2], rec["meshMax"][2]
    d = z_hi - z_lo
    g, nu = rec["g"][0], rec["nu"]
    h = d / rec["cells"][2]

    # 1. simpleFoam against the analytic parabola.
    ft = latest("simpleFoam")
    C = read_vector_field(f"simpleFoam/{ft}/C")
    U = read_vector_field(f"simpleFoam/{ft}/U")
    z = C[:, 2]
    analytic = g * (z - z_lo) * (z_hi - z) / (2 * nu)
    u_max = g * d * d / (8 * nu)
    shift = g * h * h / (8 * nu)
    solver_error = np.max(np.abs(U[:, 0] - (analytic + shift))) / u_max
    discretisation = np.max(np.abs(U[:, 0] - analytic)) / u_max

    # 2. DPD against the twin.
    zb, ud, ue, uf = prof[:, 0], prof[:, 1], prof[:, 2], prof[:, 3]
    L2, noise = cmp["L2"], cmp["noiseL2"]
    n = int(cmp["points"])
    dpd_check = ("DPD vs simpleFoam (nu without walls, no slip): L2 < 3 %", L2 < 0.03,
                 f"L2 = {L2:.4f}, noise L2 = {noise:.4f}, {n} bins")
    checks = [
        ("simpleFoam = analytic + g h^2/(8 nu) to solver precision (< 1e-8 of u_max)", solver_error < 1e-8,
         f"{solver_error:.2e}"),
        dpd_check,
    ]

    with open("resultsFVM.dat", "w") as f:
        f.write(f"# DPD channel at time {t} against simpleFoam (time {ft}): nu without walls, no slip\n")
        f.write(f"nu                {nu:.5f}  (viscosity/, no walls)\n")
        f.write(f"slipLength        {fit['slipLength'][0]:+.4f} {fit['slipLength'][1]:+.4f}  (fitSlipLength, for reference)\n")
        f.write(f"simpleFoamSolver  {solver_error:.3e}  (max |U - analytic - g h^2/8nu| / u_max)\n")
        f.write(f"discretisation    {discretisation:.3e}  (max |U - analytic| / u_max; (h/d)^2 = {(h / d) ** 2:.3e})\n")
        f.write(f"L2                {L2:.5f}\nLinf              {cmp['Linf']:.5f}\nnoiseL2           {noise:.5f}\n")
        f.write(f"meanVelocityRatio {cmp['meanVelocityRatio']:.5f}\n")
        for name, ok, value in checks:
            f.write(f"check  {'PASS' if ok else 'FAIL'}  {name}: {value}\n")
    print(open("resultsFVM.dat").read(), end="")

    fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
    zz = np.linspace(z_lo, z_hi, 200)
    ax[0].errorbar(zb, ud, yerr=ue, fmt="o", ms=3, label="DPD (profileBins)")
    ax[0].plot(z, U[:, 0], "r-", lw=1.5, label=f"simpleFoam, nu = {nu:.4f} (no walls), no slip")
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
    fig.savefig("compareFVM.png", dpi=120)
    print("Written compareFVM.png and resultsFVM.dat")
    return 0 if all(ok for _, ok, _ in checks) else 1


if __name__ == "__main__":
    sys.exit(main())
