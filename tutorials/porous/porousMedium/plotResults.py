#!/usr/bin/env python3
"""Porous medium tutorial (docs/scenes.md scene 6): pictures, results table and the checks.

Reads the DPD 2-D field (postProcessing/profileBins/<time>/flowField.dat, 1 x 1 bins), the solver's
log (kT series, particles inside the solid, run time), the simpleFoam twin (simpleFoam/<time>/C, U,
constant/dpdCase for nu), compareFVM's result (postProcessing/compareFVM/<time>/compare.dat,
profiles.dat), the built counts (log.randomEquilWall) and the paper's (published.dat, when there).
Writes porousMedium.png (DPD |u|, density, kT series, profiles across the crack),
compareFVM.png (DPD |u|, simpleFoam |u|, their difference, the crack's centre line) and results.dat;
exits non-zero when a check fails.

Checks, full scene (the issue's criteria):
  - mean kT within 3.5 % of the set kT = 1: the bins' kT (about each bin's own mean velocity), and the
    log's series (the monitor's kT is about the local flow, fitted in cells across x and z; the flow's
    kinetic energy per degree of freedom, which a global mean would have counted, is reported);
  - no fluid particle inside the solid at the end (the solver's count);
  - velocity near zero next to the grains: over the bins the grains' surface passes through, the mean
    DPD velocity is below 10 % of the crack's peak and within 3 % of that peak of the continuum's in
    the same bins (a slipping wall would leave a velocity of the order of the pore's);
  - the crack's centre line: relative L2 of DPD against simpleFoam < 10 %;
  - mean velocity within 10 %: meanVelocityRatio (over the compared bins) and the superficial velocity
    (Darcy permeability) ratio.
Each check first asserts that the noise of its quantity is within a budget (NOISE_BUDGETS below), so
that a run too noisy to decide fails instead of passing more easily; the bound is then fixed.
Test mode (40 x 40 mask, 160 time units of sampling): the same checks, each bound the full one plus
three test budgets (fixed, derived below for the shorter run). Next to the grains the bound is the
larger of 10 % of the peak and simpleFoam's own velocity there plus 3 % of the peak (in the small mask
the continuum itself has ~11 % there). In test mode the crack line (noise ~0.12 over 40 bins) only
catches gross errors (a slipping or missing wall, a unit slip); the full scene decides it.

Where the two disagree: each fluid bin gets the local pore size (the diameter of the largest disc in
the fluid that covers it, from the mask) and its distance to the solid; results.dat gives the relative
L2 and the mean-velocity ratio per class of each.
"""
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.join(os.environ.get("DPD_PROJECT_DIR", "../../.."), "etc"))
from dpdResults import latest, parse_dict, read_dict, read_published, read_table  # noqa: E402

test_mode = "-test" in sys.argv[1:]

# Noise budgets (the largest noise at which a check still decides). Full scene, measured (README;
# 2026-11-24): crack noiseL2 0.023-0.024, superficial velocity 0.12 % (relative), kT of the log's series
# 0.0005-0.0006, near-grain velocity 0.013 % of the peak; budgets about twice that. Test (160 time units on the 40 x 40 mask; measured at 40 time units:
# noiseL2 0.233, superficial 2.7 %, kT 0.0047, near-grain velocity 0.63 % of the peak; four times the
# sampling halves each): budgets 1.3 x the expected. Velocity next to the grains: standard error of
# the mean over the near-grain bins, relative to the crack's peak.
NOISE_BUDGETS = {
    False: {"line": 0.05, "mean": 0.003, "kT": 0.0012, "wall": 0.0003},
    True: {"line": 0.15, "mean": 0.018, "kT": 0.003, "wall": 0.004},
}


def read_compare(path):
    """compare.dat: the top-level entries, and each line's sub-dictionary."""
    text = open(path).read()
    head, _, rest = text.partition("\nlines")
    return parse_dict(head), {name: parse_dict(body) for name, body in re.findall(r"(\w+)\s*\{([^{}]*)\}", rest)}


def solver_log():
    text = open("log.dpdFoamLike").read()
    times = [float(v) for v in re.findall(r"^Time = ([-0-9.eE+]+)", text, re.M)]
    kts = [float(v) for v in re.findall(r"kT = ([-0-9.eE+]+)", text)]
    inside = [int(v) for v in re.findall(r"inside walls now (\d+)", text)]
    crossed = [int(v) for v in re.findall(r"geometry returned \d+ crossed (\d+);", text)]
    run = re.search(r"Run finished: (\d+) steps in ([0-9.eE+]+) s, ([0-9.eE+]+) particle-steps/s", text)
    if not kts or not inside or not run:
        sys.exit("plotResults: log.dpdFoamLike has no report or no end")
    return np.array(times[-len(kts):]), np.array(kts), inside[-1], sum(crossed), run


def built_counts():
    """The fluid and frozen particles randomEquilWall built (its log)."""
    text = open("log.randomEquilWall").read()
    fluid = re.search(r"^Fluid particles *: *(\d+)", text, re.M)
    frozen = re.search(r"^Frozen particles *: *(\d+)", text, re.M)
    if not fluid or not frozen:
        sys.exit("plotResults: log.randomEquilWall gives no particle counts")
    return int(fluid.group(1)), int(frozen.group(1))


def foam_vector_field(path):
    body = open(path).read().split("internalField", 1)[1]
    n = int(re.search(r"List<vector>\s*(\d+)", body).group(1))
    nums = re.findall(r"[-+0-9.eE]+", body[body.index("(", body.index("List<vector>")) + 1:].replace("(", " ").replace(")", " "))
    return np.array(nums[: 3 * n], float).reshape(n, 3)


def foam_on_bins(xs, zs):
    """simpleFoam's U gathered into the DPD bins (mean over the fluid cells in each; NaN in solid), and
    the fraction of each bin's cells that are fluid."""
    t = max((d for d in os.listdir("simpleFoam") if re.fullmatch(r"[0-9.eE+-]+", d) and float(d) > 0), key=float)
    C, U = foam_vector_field(f"simpleFoam/{t}/C"), foam_vector_field(f"simpleFoam/{t}/U")
    w = xs[1] - xs[0]
    i = np.floor((C[:, 0] - (xs[0] - w / 2)) / w).astype(int)
    k = np.floor((C[:, 2] - (zs[0] - w / 2)) / w).astype(int)
    out = []
    n = np.zeros((len(zs), len(xs)))
    np.add.at(n, (k, i), 1)
    for comp in (0, 2):
        s = np.zeros((len(zs), len(xs)))
        np.add.at(s, (k, i), U[:, comp])
        out.append(np.where(n > 0, s / np.maximum(n, 1), np.nan))
    return out[0], out[1], n / n.max()


def mask_solid(shape):
    """The mask's solid pixels (row 0 = bottom), from constant/dpdProperties' geometry file."""
    props = open("constant/dpdProperties").read()
    path = re.search(r'file\s+"([^"]+)"', props).group(1)
    img = plt.imread(path)
    grey = img[..., :3].mean(axis=-1) if img.ndim == 3 else img
    solid = (grey < 0.5)[::-1]
    if solid.shape != shape:
        sys.exit(f"plotResults: the mask {path} is {solid.shape}, the bins {shape}")
    return solid, path


def distance_to_solid(solid):
    """Distance from each pixel centre to the nearest solid pixel's edge (0 in the solid), periodic."""
    n0, n1 = solid.shape
    sr, sc = np.nonzero(solid)
    d = np.zeros(solid.shape)
    fr, fc = np.nonzero(~solid)
    for a in range(0, len(fr), 200):
        dr = np.abs(fr[a:a + 200, None] - sr[None, :])
        dc = np.abs(fc[a:a + 200, None] - sc[None, :])
        dr, dc = np.minimum(dr, n0 - dr), np.minimum(dc, n1 - dc)
        # to the nearest point of the solid pixel (a unit square), from the fluid pixel's centre
        ex, ez = np.maximum(dc - 0.5, 0), np.maximum(dr - 0.5, 0)
        d[fr[a:a + 200], fc[a:a + 200]] = np.sqrt(ex ** 2 + ez ** 2).min(axis=1)
    return d


def local_pore_size(dist):
    """Local thickness of the pore space: for each fluid pixel the diameter of the largest disc inside
    the fluid (centred on a fluid pixel, radius its distance to the solid) that covers it."""
    n0, n1 = dist.shape
    size = np.zeros(dist.shape)
    rr, cc = np.mgrid[0:n0, 0:n1]
    for r, c in zip(*np.nonzero(dist > 0)):
        rad = dist[r, c]
        dr = np.abs(rr - r)
        dc = np.abs(cc - c)
        dr, dc = np.minimum(dr, n0 - dr), np.minimum(dc, n1 - dc)
        cover = dr * dr + dc * dc <= rad * rad
        size[cover] = np.maximum(size[cover], 2 * rad)
    return size


def class_table(key, edges, ud, uf, err, rho, whole):
    """Per class of key: bins, L2, noise L2, flow ratio DPD/FVM, mean FVM velocity, and the mean DPD
    density of the class's bins that lie wholly in the fluid (whole; nan where none do): a throat the
    walls' repulsion reaches across is depleted, which the continuum does not know."""
    rows = []
    for lo, hi in zip(edges[:-1], edges[1:]):
        sel = (key >= lo) & (key < hi) & np.isfinite(uf) & np.isfinite(ud)
        if sel.sum() < 3:
            continue
        l2 = np.sqrt(np.sum((ud[sel] - uf[sel]) ** 2) / np.sum(uf[sel] ** 2))
        noise = np.sqrt(np.sum(err[sel] ** 2) / np.sum(uf[sel] ** 2))
        dense = sel & whole
        density = rho[dense].mean() if dense.any() else float("nan")
        rows.append((lo, hi, int(sel.sum()), l2, noise, ud[sel].sum() / uf[sel].sum(), uf[sel].mean(), density))
    return rows


def main():
    table = latest("postProcessing/profileBins/*/flowField.dat")
    g = read_table(table)
    xs, zs = np.unique(g["x"]), np.unique(g["z"])
    shape = (len(zs), len(xs))
    grid = {k: v.reshape(shape) for k, v in g.items()}
    times, kts, inside, crossed, run = solver_log()
    cmp_path = latest("postProcessing/compareFVM/*/compare.dat")
    cmp, lines = read_compare(cmp_path)
    crack = lines["crack"]
    prof = read_table(os.path.join(os.path.dirname(cmp_path), "profiles.dat"))
    twin = read_dict("simpleFoam/constant/dpdCase")   # nu and where it came from
    sample_start = float(re.search(r"startTime\s+([0-9.eE+]+);", open("system/controlDict").read().split("flowField")[1]).group(1))

    # Temperature: the bins' kT (about each bin's own flow) and the log's series (about the local flow,
    # system/Monitors); flow_kT is what a global mean would have added, for reference.
    count = grid["count"]
    fluid = count >= 10
    kT_bins = np.sum(grid["kT"][fluid] * count[fluid]) / np.sum(count[fluid])
    w = count / count.sum()
    mean_u = [np.sum(w * grid[c]) for c in ("ux", "uy", "uz")]
    flow_kT = sum(np.sum(w * (grid[c] - m) ** 2) for c, m in zip(("ux", "uy", "uz"), mean_u)) / 3
    in_window = times >= sample_start
    kT_log = kts[in_window].mean()
    # Standard error of the series' mean: reports lie 10 time units or more apart, far beyond the
    # kinetic temperature's correlation time (~1), so they count as independent.
    kT_log_err = np.std(kts[in_window], ddof=1) / np.sqrt(max(1, in_window.sum()))

    # The two fields on the bins.
    ufx, ufz, fvm_fraction = foam_on_bins(xs, zs)
    speed_dpd = np.hypot(grid["ux"], grid["uz"])
    speed_fvm = np.hypot(ufx, ufz)
    # Maps show the bins holding at least a quarter of a full bin's particles: in bins the grains'
    # surface cuts, the few particles in the sliver of fluid carry a large, biased mean (README).
    shown = count >= 0.25 * np.median(count[count > 0])
    speed_dpd = np.where(shown, speed_dpd, np.nan)
    solid, mask_path = mask_solid(shape)
    dist = distance_to_solid(solid)
    pore = local_pore_size(dist)
    compared = fluid & np.isfinite(ufx)
    ud, uf, ue = grid["ux"][compared], ufx[compared], grid["uxErr"][compared]
    # The field away from the surface: bins whose every continuum cell is fluid.
    interior = compared & (fvm_fraction == 1)
    l2_interior = np.sqrt(np.sum((grid["ux"][interior] - ufx[interior]) ** 2) / np.sum(ufx[interior] ** 2))
    noise_interior = np.sqrt(np.sum(grid["uxErr"][interior] ** 2) / np.sum(ufx[interior] ** 2))

    # Next to the grains: bins the grains' surface passes through (the bin is solid in part: both
    # sides have cells there), i.e. fluid bins adjacent to a solid pixel.
    near = compared & (dist < 0.75)
    crack_rows = np.isfinite(prof["u_crack"])
    u_peak = np.nanmax(prof["u_crack"])
    u_wall_dpd, u_wall_fvm = grid["ux"][near].mean(), ufx[near].mean()

    # Where they disagree: by local pore size and by distance to the solid.
    rho_c, whole_c = grid["density"][compared], (fvm_fraction == 1)[compared]
    by_pore = class_table(pore[compared], [0, 3, 5, 8, 12, 1e9], ud, uf, ue, rho_c, whole_c)
    by_dist = class_table(dist[compared], [0, 0.75, 1.5, 3, 1e9], ud, uf, ue, rho_c, whole_c)
    worst = max(by_pore, key=lambda r: r[3])

    ratio_super = cmp["permeabilityRatio"]
    super_err = cmp["superficialVelocityDPDErr"] / cmp["superficialVelocityFVM"]
    budget = NOISE_BUDGETS[test_mode]
    widen = 3.0 if test_mode else 0.0  # test bounds: the full bound plus three test budgets, fixed
    line_tol = 0.10 + widen * budget["line"]
    mean_tol = 0.10 + widen * budget["mean"]
    kT_tol = 0.035 + widen * budget["kT"]
    # Next to the grains: 10 % of the crack's peak. In the test's small mask the bins the grains cut
    # hold more of the flow: simpleFoam's own velocity there is ~11 % of the peak (0.0195 of 0.182),
    # so a correct no-slip run sits at the bound. There the bound is the continuum's value plus the
    # 3 %-of-peak allowance of the next check, plus three test budgets like every test bound; a
    # slipping wall (velocity of the order of the pore's) is still far above it.
    wall_se = np.sqrt(np.mean(grid["uxErr"][near] ** 2) / near.sum())
    wall_bound = 0.1 * u_peak
    if test_mode:
        wall_bound = max(wall_bound, abs(u_wall_fvm) + 0.03 * u_peak) + widen * budget["wall"] * u_peak
    noise = {"line": crack["noiseL2"], "mean": super_err, "kT": kT_log_err, "wall": wall_se / u_peak}
    checks = [
        (f"noise of the {name} within its budget {budget[name]:g}", bool(noise[name] <= budget[name]), f"{noise[name]:.4g}")
        for name in ("line", "mean", "kT", "wall")
    ] + [
        (f"mean kT of the bins within {kT_tol:.3f} of 1", abs(kT_bins - 1) < kT_tol, f"{kT_bins:.4f}"),
        (f"mean kT of the log's series within {kT_tol:.3f} of 1",
         abs(kT_log - 1) < kT_tol, f"{kT_log:.4f} +- {kT_log_err:.4f}"),
        ("no fluid particle inside the solid at the end", inside == 0, f"{inside}"),
        (f"velocity next to the grains < {wall_bound / u_peak:.1%} of the crack's peak", abs(u_wall_dpd) < wall_bound,
         f"{u_wall_dpd:.4f} (peak {u_peak:.4f})"),
        ("velocity next to the grains within 3 % of the peak of simpleFoam's there",
         abs(u_wall_dpd - u_wall_fvm) < 0.03 * u_peak + widen * budget["wall"] * u_peak,
         f"DPD {u_wall_dpd:.4f}, simpleFoam {u_wall_fvm:.4f} over {near.sum()} bins"),
        (f"crack centre line: relative L2 < {line_tol:.3f}", crack["L2"] < line_tol,
         f"{crack['L2']:.4f} (noise {crack['noiseL2']:.4f}, {int(crack['points'])} bins)"),
        (f"mean velocity over the compared bins within {mean_tol:.3f}", abs(cmp["meanVelocityRatio"] - 1) < mean_tol,
         f"{cmp['meanVelocityRatio']:.4f}"),
        (f"superficial velocity (permeability) within {mean_tol:.3f}", abs(ratio_super - 1) < mean_tol,
         f"{ratio_super:.4f} +- {super_err:.4f}"),
    ]

    steps, seconds, rate = int(run.group(1)), float(run.group(2)), float(run.group(3))
    # The system's kT over the whole run (the log's series about the local flow): its largest
    # deviation from the set kT, a quantity the paper reports.
    worst_kT = int(np.argmax(np.abs(kts - 1.0)))
    fluid_built, frozen_built = built_counts()
    paper = read_published("published.dat")["tables"].get("counts") if os.path.exists("published.dat") else None
    with open("results.dat", "w") as f:
        f.write(f"# Porous medium (docs/scenes.md scene 6){' - TEST MODE' if test_mode else ''}: {table}, {cmp_path}\n")
        f.write(f"mask               {mask_path}  ({shape[1]} x {shape[0]} bins of 1 r_c)\n")
        f.write(f"porosity           DPD {cmp['porosityDPD']:.4f}  simpleFoam {cmp['porosityFVM']:.4f}"
                + (f"  published {paper['porosity'][0]:g}" if paper else "") + "\n")
        f.write(f"particles          fluid {fluid_built}  frozen {frozen_built} (every solid particle within one cutoff"
                f" of the fluid; {frozen_built / (fluid_built + frozen_built):.1%} of all)"
                + (f"; published fluid {paper['fluid'][0]:.0f}, frozen {paper['frozen'][0]:.0f}"
                   f" ({paper['frozen'][0] / (paper['fluid'][0] + paper['frozen'][0]):.1%})" if paper else "") + "\n")
        f.write(f"nu                 {twin['nu']:.5f}  ({twin['nuSource']})\n")
        f.write(f"runTime            {seconds:.0f} s for {steps} steps; {rate:.4g} particle-steps/s\n")
        f.write(f"kTSeries           (" + " ".join(f"{t:g}:{k:.4f}" for t, k in zip(times, kts)) + ")\n")
        f.write(f"kTLog              {kT_log:.5f} +- {kT_log_err:.5f}  (mean of the series from t = {sample_start:g})\n")
        f.write(f"kTFlowPart         {flow_kT:.5f}  (flow's kinetic energy per degree of freedom, from the bins: what a global mean would add)\n")
        f.write(f"kTBins             {kT_bins:.5f}\n")
        f.write(f"kTMaxDeviation     {kts[worst_kT] - 1:+.5f}  (largest of the log's {len(kts)} reports over the run, at t = {times[worst_kT]:g})\n")
        f.write(f"insideAtEnd        {inside}\ncrossedBounceLayer {crossed}  (whole run)\n")
        f.write(f"uNextToGrains      DPD {u_wall_dpd:.5f}  simpleFoam {u_wall_fvm:.5f}  crack peak {u_peak:.4f}\n")
        f.write(f"L2field            {cmp['L2']:.5f}  (noise {cmp['noiseL2']:.5f}; Linf {cmp['Linf']:.4f})\n")
        f.write(f"L2interior         {l2_interior:.5f}  (noise {noise_interior:.5f}; {interior.sum()} bins whose continuum cells are all fluid)\n")
        f.write(f"L2crack            {crack['L2']:.5f}  (noise {crack['noiseL2']:.5f}; Linf {crack['Linf']:.4f}; mean ratio {crack['meanVelocityRatio']:.4f})\n")
        f.write(f"meanVelocityRatio  {cmp['meanVelocityRatio']:.5f}  (DPD {cmp['meanVelocityDPD']:.5f}, simpleFoam {cmp['meanVelocityFVM']:.5f})\n")
        f.write(f"superficialVelocity DPD {cmp['superficialVelocityDPD']:.6f} +- {cmp['superficialVelocityDPDErr']:.6f}  simpleFoam {cmp['superficialVelocityFVM']:.6f}\n")
        f.write(f"permeabilityDPD    {cmp['permeabilityDPD']:.5f} +- {cmp['permeabilityDPDErr']:.5f}\n")
        f.write(f"permeabilityFVM    {cmp['permeabilityFVM']:.5f}\npermeabilityRatio  {ratio_super:.5f}\n")
        f.write("# by local pore size (diameter of the largest fluid disc covering the bin): lo hi bins L2 noiseL2 meanRatio uFVMmean densityWholeBins\n")
        for r in by_pore:
            f.write(f"poreSize  {r[0]:g} {r[1]:g} {r[2]} {r[3]:.4f} {r[4]:.4f} {r[5]:.4f} {r[6]:.5f} {r[7]:.3f}\n")
        f.write("# by distance from the bin centre to the solid: lo hi bins L2 noiseL2 meanRatio uFVMmean densityWholeBins\n")
        for r in by_dist:
            f.write(f"wallDistance {r[0]:g} {r[1]:g} {r[2]} {r[3]:.4f} {r[4]:.4f} {r[5]:.4f} {r[6]:.5f} {r[7]:.3f}\n")
        f.write(f"worstPoreClass     {worst[0]:g}-{worst[1]:g}: L2 {worst[3]:.4f}, mean ratio {worst[5]:.4f}\n")
        for name, ok, value in checks:
            f.write(f"check  {'PASS' if ok else 'FAIL'}  {name}: {value}\n")
    print(open("results.dat").read(), end="")

    ext = [xs[0] - 0.5, xs[-1] + 0.5, zs[0] - 0.5, zs[-1] + 0.5]
    fig, ax = plt.subplots(2, 2, figsize=(13, 11))
    im = ax[0, 0].imshow(speed_dpd, origin="lower", extent=ext, cmap="viridis")
    fig.colorbar(im, ax=ax[0, 0], label="|u|")
    ax[0, 0].set_title("DPD |u| (flowField.vti)")
    dens = np.where(count > 0, grid["density"], np.nan)
    im = ax[0, 1].imshow(dens, origin="lower", extent=ext, cmap="magma")
    fig.colorbar(im, ax=ax[0, 1], label="number density")
    ax[0, 1].set_title("DPD density")
    ax[1, 0].plot(times, kts, "o-", ms=3, label="log: kT about the local flow")
    ax[1, 0].axhline(1 + flow_kT, color="gray", ls=":", label=f"1 + flow part {flow_kT:.4f} (a global mean)")
    ax[1, 0].axhline(kT_bins, color="r", ls="--", label=f"bins (about local flow): {kT_bins:.4f}")
    ax[1, 0].axhline(1, color="k", lw=0.8)
    ax[1, 0].axvline(sample_start, color="k", ls=":", lw=0.8)
    ax[1, 0].set_xlabel("time")
    ax[1, 0].set_ylabel("kT")
    ax[1, 0].legend(fontsize=8)
    ax[1, 0].set_title(f"kT series; {inside} particles inside the solid at the end")
    for path in sorted(os.listdir(os.path.dirname(table))):
        m = re.fullmatch(r"flowField_x(.*)\.dat", path)
        if not m:
            continue
        s = read_table(os.path.join(os.path.dirname(table), path))
        col = int(np.argmin(np.abs(xs - float(m.group(1)))))
        ok = s["count"] >= 10
        line = ax[1, 1].errorbar(s["z"][ok], s["ux"][ok], yerr=s["uxErr"][ok], fmt="o", ms=2, label=f"DPD x = {m.group(1)}")
        ax[1, 1].plot(zs, ufx[:, col], "-", color=line[0].get_color(), lw=1, label=f"simpleFoam x = {m.group(1)}")
    ax[1, 1].set_xlabel("z")
    ax[1, 1].set_ylabel("ux")
    ax[1, 1].legend(fontsize=8)
    ax[1, 1].set_title("across the crack, narrowest and widest")
    fig.tight_layout()
    fig.savefig("porousMedium.png", dpi=110)

    fig, ax = plt.subplots(2, 2, figsize=(13, 11))
    vmax = np.nanmax(speed_fvm)
    for a, field, title in ((ax[0, 0], speed_dpd, "DPD |u|"), (ax[0, 1], speed_fvm, "simpleFoam |u| (on the DPD bins)")):
        im = a.imshow(field, origin="lower", extent=ext, cmap="viridis", vmin=0, vmax=vmax)
        fig.colorbar(im, ax=a, label="|u|")
        a.set_title(title)
    diff = np.where(compared & shown, grid["ux"] - ufx, np.nan)
    lim = np.nanpercentile(np.abs(diff), 99)
    im = ax[1, 0].imshow(diff, origin="lower", extent=ext, cmap="RdBu_r", vmin=-lim, vmax=lim)
    fig.colorbar(im, ax=ax[1, 0], label="ux DPD - ux simpleFoam")
    ax[1, 0].set_title(f"difference: L2 field {cmp['L2']:.3f}, interior {l2_interior:.3f}", fontsize=10)
    on = crack_rows
    ax[1, 1].errorbar(prof["x"][on], prof["uDPD"][on], yerr=prof["uDPDErr"][on], fmt="o", ms=2, label="DPD (bins on the line)")
    ax[1, 1].plot(prof["x"][on], prof["u_crack"][on], "r-", lw=1.2, label=f"simpleFoam, nu = {twin['nu']:.4f}")
    ax[1, 1].set_xlabel("x")
    ax[1, 1].set_ylabel("ux on the crack's centre line")
    ax[1, 1].legend(fontsize=8)
    ax[1, 1].set_title(f"crack centre line: L2 {crack['L2']:.4f}; k DPD/FVM {ratio_super:.3f}")
    fig.tight_layout()
    fig.savefig("compareFVM.png", dpi=110)
    print("Written porousMedium.png, compareFVM.png and results.dat")
    return 0 if all(ok for _, ok, _ in checks) else 1


if __name__ == "__main__":
    sys.exit(main())
