#!/usr/bin/env python3
"""Single chains in a good solvent: <R_g^2> against N, the Flory exponent nu, table and checks.

For every sweep/N<N>/ case the chainStatistics table (postProcessing/chains/<time>/chainStatistics.dat:
means over the chains at each sample, and in its header each mean with its block standard error).
nu comes from a weighted straight-line fit of ln <R_g^2> = 2 nu ln N + c; its error from the fit's
covariance, scaled up by sqrt(chi^2/dof) when the points scatter more than their errors say.
Writes results.dat and scaling.png; exits non-zero when a check fails.
"""
import glob
import os
import sys

import numpy as np

from dpdfoam.checks import Checks, print_file
from dpdfoam.io import header_means, latest, read_text, run_finished
from dpdfoam.plots import plt, save

NU_SAW = 0.588  # the self-avoiding walk (renormalisation group)
NU_BOUND = 0.04  # the full run's bound on |nu - NU_SAW| (main: why)
NU_ERROR_BUDGET = 0.01


def fit_exponent(n, rg2, err):
    """Weighted fit of ln rg2 = 2 nu ln n + c: nu, its error, chi^2/dof. (No C++ tool fits a power law:
    the one fit of the tutorials' Python that is not a tool's.)"""
    x, y, w = np.log(n), np.log(rg2), (rg2 / err) ** 2  # sigma of ln rg2 = err / rg2
    a = np.vstack([x, np.ones_like(x)]).T
    cov = np.linalg.inv(a.T @ (a * w[:, None]))
    slope, c = cov @ (a.T @ (w * y))
    dof = max(len(x) - 2, 1)
    chi2 = float(np.sum(w * (y - (slope * x + c)) ** 2)) / dof
    return slope / 2, np.sqrt(cov[0, 0] * max(chi2, 1.0)) / 2, chi2, c


def case_row(d):
    """N, <R_g^2> and <R_ee^2> with their errors, the run's seconds and particle-steps per second."""
    means = header_means(latest(os.path.join(d, "postProcessing/chains/*/chainStatistics.dat")))
    _, seconds, rate = run_finished(read_text(os.path.join(d, "log.dpdFoamLike")))
    return (int(d.split("N")[-1]), *means["Rg2"], *means["Ree2"], seconds, rate)


def main():
    test = "-test" in sys.argv[1:]
    rows = np.array([case_row(d) for d in sorted(glob.glob("sweep/N*"), key=lambda p: int(p.split("N")[-1]))])
    n, rg2, rg2e, ree2, ree2e = rows[:, 0], rows[:, 1], rows[:, 2], rows[:, 3], rows[:, 4]
    nu, nu_err, chi2, c = fit_exponent(n, rg2, rg2e)
    checks = Checks()
    if test:
        # Test mode (150 time units): only that R_g^2 grows with N, decided from the errors: the
        # largest chain's R_g^2 above the smallest's by more than 3 combined errors.
        diff, comb = rg2[-1] - rg2[0], np.hypot(rg2e[-1], rg2e[0])
        checks.add("R_g^2 grows with N", diff > 3 * comb, f"{rg2[-1]:.3f} - {rg2[0]:.3f} = {diff:.3f} > 3 x {comb:.3f}")
    else:
        # The exponent of a self-avoiding chain: first its error within the budget (measured 0.005 at
        # full size; twice that still decides), then nu within a fixed 0.04 of the self-avoiding walk's
        # 0.588, the room the effective exponent over N 10-60 needs for its corrections to scaling
        # (short chains' soft bonds) while an ideal chain's 1/2 lies more than twice as far.
        checks.add("error of nu within its budget 0.01", nu_err <= NU_ERROR_BUDGET, f"{nu_err:.4f}")
        checks.add(f"self-avoiding chains: nu within {NU_BOUND} of {NU_SAW}", abs(nu - NU_SAW) < NU_BOUND,
                   f"nu = {nu:.4f} +- {nu_err:.4f}")
    with open("results.dat", "w") as f:
        f.write("# Single FENE chains (H 6, r_max 3) in the polymer scene's solvent (rho 4, a 18.75, gamma 4.5)\n")
        f.write(f"# nu {nu:.4f} +- {nu_err:.4f} (fit of ln R_g^2 = 2 nu ln N + c, chi2/dof {chi2:.2f}); self-avoiding walk {NU_SAW}, ideal 0.5\n")
        checks.write(f, "# check {verdict}: {name}: {value}")
        f.write("# N Rg2 Rg2Err Ree2 Ree2Err Ree2/Rg2 seconds particleStepsPerSecond\n")
        for r in rows:
            f.write(f"{int(r[0])} {r[1]:.5f} {r[2]:.5f} {r[3]:.5f} {r[4]:.5f} {r[3] / r[1]:.3f} {r[5]:.1f} {r[6]:.4g}\n")
    print_file("results.dat")
    print()
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    ax[0].errorbar(n, rg2, yerr=rg2e, fmt="o", label="DPD")
    nn = np.linspace(n.min(), n.max(), 50)
    ax[0].plot(nn, np.exp(c) * nn ** (2 * nu), label=f"fit: nu = {nu:.3f} +- {nu_err:.3f}")
    ax[0].plot(nn, rg2[0] * (nn / n[0]) ** (2 * NU_SAW), "--", label=f"slope nu = {NU_SAW} (SAW)")
    ax[0].plot(nn, rg2[0] * (nn / n[0]), ":", label="slope nu = 1/2 (ideal)")
    ax[0].set_xscale("log"), ax[0].set_yscale("log")
    ax[0].set_xlabel("N (beads)"), ax[0].set_ylabel("<R_g^2>"), ax[0].legend()
    ratio = ree2 / rg2
    ax[1].errorbar(n, ratio, yerr=ratio * np.hypot(ree2e / ree2, rg2e / rg2), fmt="o")
    ax[1].axhline(6.0, color="k", lw=0.8, label="ideal 6")
    ax[1].axhline(6.25, color="k", ls="--", lw=0.8, label="SAW ~6.25")
    ax[1].set_xlabel("N"), ax[1].set_ylabel("<R_ee^2> / <R_g^2>"), ax[1].legend()
    save(fig, "scaling.png", dpi=120)
    return checks.status()


if __name__ == "__main__":
    sys.exit(main())
