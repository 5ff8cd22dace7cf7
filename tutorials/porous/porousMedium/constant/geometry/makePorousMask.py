#!/usr/bin/env python3
"""The porous medium of docs/scenes.md scene 6 as an image mask (1 pixel = 1 r_c; black = solid).

Grains of varied size and shape: the periodic Voronoi cells of Poisson-disc seeds of three sizes,
each shrunk by its own throat half-width (the common scale set by bisection so that the solid covers
the target fraction of the box), wrapped in both directions (the DPD box is periodic). A crack
parallel to the flow (x) runs along the middle: no grain reaches into it; its width varies smoothly
along x (a periodic wave) about a mean wider than the typical pore, so the crack itself has throats
and bulges.

The solid the tools see is the 1/2 contour of the mask after the binomial (1 4 6 4 1)/16 filter of
libdpd/geometry/ImageMask (smooth yes): pores thinner than ~2 pixels close there. The continuum mesh
(makeFoamCase) cuts the cells whose centres are solid in that smoothed mask, so an isolated pocket of
fluid there would be a region whose pressure has no level. The script therefore evaluates the smoothed
mask exactly as the C++ does (filter, bilinear interpolation, >= 1/2) on the cell centres of a 0.5 r_c
mesh and fills every fluid pocket not connected to the main fluid, repeating until there is one fluid
region. Checks (exit status 1 when one fails): porosity of the smoothed contour (what the tools see)
within 0.005 of the target and of the pixel mask within 0.03, one fluid region, the fluid percolates
along x (a path from the left edge to the right one without using the periodic wrap in x).

    makePorousMask.py OUT.png SIZE [--seed S] [--solid 0.56] [--crack W]

Writes OUT.png and OUT.dat (its statistics: porosity, crack centre row and widths). Deterministic:
the same arguments give the same picture.
"""
import argparse
import sys

import numpy as np

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# Grain seeds: dart throwing with an exclusion radius drawn per seed from these classes (pixels), so
# grains come in several sizes; each grain is the seed's periodic Voronoi cell shrunk by its own
# throat half-width, so grain shapes are irregular polygons of 4-8 sides and the pores between them
# form one connected network of throats of varied width (no closed pocket by construction).
RADII = np.array([5.0, 7.5, 11.0])
SHARE = np.array([0.45, 0.35, 0.20])
# Throat half-width of each grain relative to the common scale: varied throats.
THROAT_SPREAD = (0.6, 1.6)


def seeds(rng, size, n_tries=20000):
    """Poisson-disc seeds (periodic) with radii drawn from RADII."""
    pts, radii = [], []
    for _ in range(n_tries):
        p = rng.uniform(0, size, 2)
        r = rng.choice(RADII, p=SHARE)
        if pts:
            d = np.abs(np.array(pts) - p)
            d = np.minimum(d, size - d)
            if np.any(np.hypot(d[:, 0], d[:, 1]) < r + np.array(radii)):
                continue
        pts.append(p)
        radii.append(r)
    return np.array(pts), np.array(radii)


def distance_to_cell_edge(size, pts):
    """For every pixel centre: its nearest seed and the distance to that seed's Voronoi cell edge
    (the nearest bisector), periodic. Row by row to keep the arrays small."""
    images = [(a, b) for a in (-1, 0, 1) for b in (-1, 0, 1)]
    allp = np.array([p + size * np.array(o) for p in pts for o in images])   # (row, col) with images
    owner_of = np.repeat(np.arange(len(pts)), len(images))
    owner = np.zeros((size, size), int)
    edge = np.zeros((size, size))
    cols = np.arange(size) + 0.5
    for r in range(size):
        d2 = (r + 0.5 - allp[:, 0]) ** 2 + (cols[:, None] - allp[:, 1]) ** 2     # (columns, seeds)
        nearest = np.argmin(d2, axis=1)
        pn = allp[nearest]
        sep = np.hypot(allp[:, 0] - pn[:, 0, None], allp[:, 1] - pn[:, 1, None])
        with np.errstate(divide="ignore", invalid="ignore"):
            e = np.where(sep > 0, (d2 - d2[np.arange(size), nearest][:, None]) / (2 * sep), np.inf)
        owner[r] = owner_of[nearest]
        edge[r] = e.min(axis=1)
    return owner, edge


def smoothed(solid):
    """The (1 4 6 4 1)/16 filter along each axis, periodic (ImageMask's PixelMask::smooth)."""
    w = np.array([1, 4, 6, 4, 1]) / 16.0
    out = solid.astype(float)
    for axis in (0, 1):
        out = sum(wk * np.roll(out, 2 - k, axis=axis) for k, wk in enumerate(w))
    return out


def solid_at_subcells(values, sub):
    """Solid at the centres of a mesh of `sub` cells per pixel: the bilinear interpolation of the
    pixel-centre values >= 1/2 (periodic). Rows and columns as in `values` (row 0 = bottom)."""
    n0, n1 = values.shape
    centres = (np.arange(sub) + 0.5) / sub - 0.5  # offsets from the pixel centre, in pixels
    out = np.zeros((n0 * sub, n1 * sub), bool)
    for a, oa in enumerate(centres):
        for b, ob in enumerate(centres):
            ja, fa = int(np.floor(oa)), oa - np.floor(oa)
            jb, fb = int(np.floor(ob)), ob - np.floor(ob)
            v00 = np.roll(values, (-ja, -jb), axis=(0, 1))
            v10 = np.roll(values, (-ja - 1, -jb), axis=(0, 1))
            v01 = np.roll(values, (-ja, -jb - 1), axis=(0, 1))
            v11 = np.roll(values, (-ja - 1, -jb - 1), axis=(0, 1))
            v = (1 - fa) * (1 - fb) * v00 + fa * (1 - fb) * v10 + (1 - fa) * fb * v01 + fa * fb * v11
            out[a::sub, b::sub] = v >= 0.5
    return out


def label(fluid, periodic_x=True):
    """Connected fluid regions (4-neighbours; periodic in rows, and in columns when periodic_x):
    an array of labels (the root cell of each region), -1 in the solid. Union-find."""
    n0, n1 = fluid.shape
    parent = np.arange(fluid.size)

    def root(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    flat = fluid.ravel()
    for r in range(n0):
        for c in range(n1):
            i = r * n1 + c
            if not flat[i]:
                continue
            for j in (((r + 1) % n0) * n1 + c, r * n1 + (c + 1) % n1 if (periodic_x or c + 1 < n1) else -1):
                if j >= 0 and flat[j]:
                    a, b = root(i), root(j)
                    if a != b:
                        parent[max(a, b)] = min(a, b)
    return np.where(flat, [root(i) for i in range(fluid.size)], -1).reshape(fluid.shape)


def fill_pockets(solid, sub=2):
    """The solid with every fluid pocket of the smoothed mask (seen at `sub` cells per pixel) that is
    not connected to the main fluid filled; and the fluid cells at that resolution."""
    solid = solid.copy()
    size = solid.shape[0]
    for _ in range(20):
        cells = ~solid_at_subcells(smoothed(solid), sub)
        lab = label(cells)
        ids, counts = np.unique(lab[lab >= 0], return_counts=True)
        if len(ids) == 1:
            break
        pockets = (lab >= 0) & (lab != ids[np.argmax(counts)])
        solid |= pockets.reshape(size, sub, size, sub).any(axis=(1, 3))
    return solid, cells


def make_mask(size, seed, solid_target, crack_mean):
    rng = np.random.default_rng(seed)
    rows = np.mgrid[0:size, 0:size][0].astype(float)  # row 0 = bottom (z up), column = x
    centre_row = size // 2
    # Crack half-width along x: a periodic wave (two harmonics) about crack_mean / 2.
    x = np.arange(size)
    half = 0.5 * crack_mean * (1 + 0.25 * np.sin(2 * np.pi * x / size + rng.uniform(0, 2 * np.pi))
                               + 0.15 * np.sin(4 * np.pi * x / size + rng.uniform(0, 2 * np.pi)))
    half = np.floor(half).astype(int)
    crack = np.abs(rows - centre_row) <= half[None, :]
    pts, _ = seeds(rng, size)
    owner, edge = distance_to_cell_edge(size, pts)
    throat = rng.uniform(*THROAT_SPREAD, len(pts))[owner]
    # The common throat scale by bisection: the solid fraction falls as the throats widen.
    lo, hi = 0.0, 10.0
    for _ in range(30):   # on the smoothed contour: the solid the DPD and the continuum mesh see
        mid = 0.5 * (lo + hi)
        if np.mean(solid_at_subcells(smoothed((edge > mid * throat) & ~crack), 2)) > solid_target:
            lo = mid
        else:
            hi = mid
    solid, cells = fill_pockets((edge > hi * throat) & ~crack)
    return solid, half, centre_row, cells, hi * np.array(THROAT_SPREAD)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("output")
    p.add_argument("size", type=int)
    p.add_argument("--seed", type=int, default=6)
    p.add_argument("--solid", type=float, default=0.56)
    p.add_argument("--crack", type=float, default=12.0, help="mean crack width in pixels")
    a = p.parse_args()
    solid, half, centre_row, cells, throats = make_mask(a.size, a.seed, a.solid, a.crack)

    porosity = 1 - solid.mean()
    porosity_smooth = cells.mean()
    one_region = len(np.unique(label(cells)[cells])) == 1
    lab = label(cells, periodic_x=False)
    percolates = bool(np.intersect1d(lab[:, 0][lab[:, 0] >= 0], lab[:, -1][lab[:, -1] >= 0]).size)
    checks = [("porosity of the mask within 0.03 of the target", abs(porosity - (1 - a.solid)) < 0.03),
              ("porosity of the smoothed contour within 0.005 of the target", abs(porosity_smooth - (1 - a.solid)) < 0.005),
              ("one fluid region (no isolated pocket)", one_region),
              ("the fluid percolates along x", percolates)]

    image = np.where(solid, 0, 255).astype(np.uint8)[::-1]  # row 0 of the picture = top = largest z
    plt.imsave(a.output, image, cmap="gray", vmin=0, vmax=255)
    widths = 2 * half + 1
    stem = a.output.rsplit(".", 1)[0]
    with open(stem + ".dat", "w") as f:
        f.write(f"# {a.output}: makePorousMask.py {a.output} {a.size} --seed {a.seed} --solid {a.solid} --crack {a.crack}\n")
        f.write(f"size              {a.size};\n")
        f.write(f"solidFraction     {1 - porosity:.4f};   // pixels\n")
        f.write(f"porosity          {porosity:.4f};\n")
        f.write(f"porositySmoothed  {porosity_smooth:.4f};   // the 1/2 contour of the smoothed mask, 0.5-pixel cells\n")
        f.write(f"throatHalfWidth   ({throats[0]:.3f} {throats[1]:.3f});   // range over the grains, pixels\n")
        f.write(f"crackCentreRow    {centre_row};   // from the bottom; centre at {centre_row + 0.5} pixels above the lower edge\n")
        f.write(f"crackWidthMean    {widths.mean():.2f};\n")
        f.write(f"crackWidthMin     {widths.min()};\ncrackWidthMax     {widths.max()};\n")
        f.write("crackWidth        (" + " ".join(str(w) for w in widths) + ");   // per column (x)\n")
        for name, ok in checks:
            f.write(f"// check {'PASS' if ok else 'FAIL'}: {name}\n")
    print(open(stem + ".dat").read(), end="")
    return 0 if all(ok for _, ok in checks) else 1


if __name__ == "__main__":
    sys.exit(main())
