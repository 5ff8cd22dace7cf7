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
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.join(os.environ.get("DPD_PROJECT_DIR", os.path.join(os.path.dirname(__file__), "../../..")), "etc"))
from dpdResults import latest  # noqa: E402

NU_SAW = 0.588  # the self-avoiding walk (renormalisation group)
NU_BOUND = 0.04  # the full run's bound on |nu - NU_SAW| (main: why)
NU_ERROR_BUDGET = 0.01


def header_means(path):
    """{name: (mean, error)} from the '# mean <name> <value> +- <error>' lines."""
    means = {}
    for line in open(path):
        m = re.match(r"# mean (\S+)\s+(\S+) \+- (\S+)", line)
        if m:
            means[m.group(1)] = (float(m.group(2)), float(m.group(3)))
    return means


def run_seconds(log):
    m = re.search(r"Run finished: \d+ steps in (\S+) s, (\S+) particle-steps/s", open(log).read())
    return (float(m.group(1)), float(m.group(2))) if m else (float("nan"), float("nan"))


def fit_exponent(n, rg2, err):
    """Weighted fit of ln rg2 = 2 nu ln n + c: nu, its error, chi^2/dof."""
    x, y, w = np.log(n), np.log(rg2), (rg2 / err) ** 2  # sigma of ln rg2 = err / rg2
    a = np.vstack([x, np.ones_like(x)]).T
    cov = np.linalg.inv(a.T @ (a * w[:, None]))
    slope, c = cov @ (a.T @ (w * y))
    dof = max(len(x) - 2, 1)
    chi2 = float(np.sum(w * (y - (slope * x + c)) ** 2)) / dof
    return slope / 2, np.sqrt(cov[0, 0] * max(chi2, 1.0)) / 2, chi2, c


def main():
    test = "-test" in sys.argv[1:]
    rows = []
    for d in sorted(glob.glob("sweep/N*"), key=lambda p: int(p.split("N")[-1])):
        n = int(d.split("N")[-1])
        m = header_means(latest(os.path.join(d, "postProcessing/chains/*/chainStatistics.dat")))
        seconds, rate = run_seconds(os.path.join(d, "log.dpdFoamLike"))
        rows.append((n, *m["Rg2"], *m["Ree2"], seconds, rate))
    rows = np.array(rows)
    n, rg2, rg2e, ree2, ree2e = rows[:, 0], rows[:, 1], rows[:, 2], rows[:, 3], rows[:, 4]
    nu, nu_err, chi2, c = fit_exponent(n, rg2, rg2e)
    checks = []
    if test:
        # Test mode (150 time units): only that R_g^2 grows with N, decided from the errors: the
        # largest chain's R_g^2 above the smallest's by more than 3 combined errors.
        diff, comb = rg2[-1] - rg2[0], np.hypot(rg2e[-1], rg2e[0])
        checks.append(("R_g^2 grows with N", diff > 3 * comb, f"{rg2[-1]:.3f} - {rg2[0]:.3f} = {diff:.3f} > 3 x {comb:.3f}"))
    else:
        # The exponent of a self-avoiding chain: first its error within the budget (measured 0.005 at
        # full size; twice that still decides), then nu within a fixed 0.04 of the self-avoiding walk's
        # 0.588, the room the effective exponent over N 10-60 needs for its corrections to scaling
        # (short chains' soft bonds) while an ideal chain's 1/2 lies more than twice as far.
        checks.append(("error of nu within its budget 0.01", bool(nu_err <= NU_ERROR_BUDGET), f"{nu_err:.4f}"))
        checks.append((f"self-avoiding chains: nu within {NU_BOUND} of {NU_SAW}", bool(abs(nu - NU_SAW) < NU_BOUND),
                       f"nu = {nu:.4f} +- {nu_err:.4f}"))
    ok = all(c[1] for c in checks)
    with open("results.dat", "w") as f:
        f.write("# Single FENE chains (H 6, r_max 3) in the polymer scene's solvent (rho 4, a 18.75, gamma 4.5)\n")
        f.write(f"# nu {nu:.4f} +- {nu_err:.4f} (fit of ln R_g^2 = 2 nu ln N + c, chi2/dof {chi2:.2f}); self-avoiding walk {NU_SAW}, ideal 0.5\n")
        for name, passed, text in checks:
            f.write(f"# check {'PASS' if passed else 'FAIL'}: {name}: {text}\n")
        f.write("# N Rg2 Rg2Err Ree2 Ree2Err Ree2/Rg2 seconds particleStepsPerSecond\n")
        for r in rows:
            f.write(f"{int(r[0])} {r[1]:.5f} {r[2]:.5f} {r[3]:.5f} {r[4]:.5f} {r[3] / r[1]:.3f} {r[5]:.1f} {r[6]:.4g}\n")
    print(open("results.dat").read())
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
    fig.tight_layout()
    fig.savefig("scaling.png", dpi=120)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
