"""Regions of an image mask (a geometry { type imageMask; } of constant/dpdProperties): its solid at the
centres of a case's bins, the distance to the solid and the local pore size of the fluid, and the open
band of rows fluid across the whole width (a crack along x), in pixels and in the box's units, and
whether a line runs along such a band."""
import subprocess
import sys

import numpy as np

from .io import dictionary_value, vector


def read_image_mask(path, rule=None):
    """An image mask's solid pixels, row 0 the bottom (the picture's last row, the smallest z, as the
    tools place it). A pixel's grey is the solver's (geometry/GreyImage.cpp): its level (0..255 in an
    8-bit image), a colour pixel's the luminance 0.299 R + 0.587 G + 0.114 B. rule: which pixels are
    solid, as a case says it (mask_rule: ("solidBelow", t), ("solidAbove", t) or ("solidValues", levels),
    geometry/ImageMask.cpp); by default the dark ones, grey below half the full scale."""
    from PIL import Image

    with Image.open(path) as image:
        if image.mode in ("P", "1"):  # VTK expands a palette to colours, 1-bit grey to 0 and 255
            image = image.convert("RGBA" if image.mode == "P" else "L")
        full = 65535.0 if image.mode.startswith("I") else 255.0
        img = np.asarray(image, dtype=float)
    if img.ndim == 3 and img.shape[-1] >= 3:
        grey = 0.299 * img[..., 0] + 0.587 * img[..., 1] + 0.114 * img[..., 2]
    else:
        grey = img[..., 0] if img.ndim == 3 else img  # grey (+ alpha)
    kind, level = rule if rule is not None else ("solidBelow", 0.5 * full)
    solid = grey < level if kind == "solidBelow" else grey > level if kind == "solidAbove" else np.isin(grey, level)
    return solid[::-1]


def mask_rule(props):
    """Which pixels a case's imageMask (constant/dpdProperties) makes solid, as the solver reads it
    (geometry/GeometryDictionary.cpp: exactly one of solidValues, solidBelow, solidAbove): ("solidValues",
    levels), ("solidBelow", t) or ("solidAbove", t); exits without exactly one."""
    given = []
    for key in ("solidValues", "solidBelow", "solidAbove"):
        try:
            given.append((key, dictionary_value(props, f"geometry/{key}")))
        except subprocess.CalledProcessError:
            pass
    if len(given) != 1:
        sys.exit(f"{props}: say which pixels are solid with exactly one of solidValues, solidBelow, solidAbove")
    key, text = given[0]
    return key, vector(text) if key == "solidValues" else float(text)


def case_mask(case="."):
    """The case's mask (constant/dpdProperties geometry/file, its solid as the case says: mask_rule), its
    path, and the box it covers in x and z (system/randomEquilWallDict): (solid, path, (lower x, lower z),
    (upper x, upper z))."""
    props = f"{case}/constant/dpdProperties"
    path = dictionary_value(props, "geometry/file").strip('"')
    lo, hi = (vector(dictionary_value(f"{case}/system/randomEquilWallDict", f"box/{k}")) for k in ("min", "max"))
    return read_image_mask(f"{case}/{path}" if case != "." else path, mask_rule(props)), path, lo[[0, 2]], hi[[0, 2]]


def on_grid(solid, lo, hi, xs, zs):
    """The mask's solid at the points (xs, zs) of a grid (bin centres; rows z, columns x), the mask
    covering the box [lo, hi] whatever its pixel size."""
    column = np.clip(np.floor((xs - lo[0]) / (hi[0] - lo[0]) * solid.shape[1]).astype(int), 0, solid.shape[1] - 1)
    row = np.clip(np.floor((zs - lo[1]) / (hi[1] - lo[1]) * solid.shape[0]).astype(int), 0, solid.shape[0] - 1)
    return solid[np.ix_(row, column)]


def case_regions_on_grid(xs, zs, case="."):
    """The case's mask (case_mask) at a grid's points (on_grid): its path, the distance to the solid
    (distance_to_solid) and the local pore size (local_pore_size) there."""
    solid, path, lo, hi = case_mask(case)
    dist = distance_to_solid(on_grid(solid, lo, hi, xs, zs))
    return path, dist, local_pore_size(dist)


def distance_to_solid(solid):
    """Distance from each cell centre to the nearest solid cell's edge (0 in the solid), periodic, in cells."""
    n0, n1 = solid.shape
    sr, sc = np.nonzero(solid)
    d = np.zeros(solid.shape)
    fr, fc = np.nonzero(~solid)
    for a in range(0, len(fr), 200):
        dr = np.abs(fr[a:a + 200, None] - sr[None, :])
        dc = np.abs(fc[a:a + 200, None] - sc[None, :])
        dr, dc = np.minimum(dr, n0 - dr), np.minimum(dc, n1 - dc)
        # to the nearest point of the solid cell (a unit square), from the fluid cell's centre
        ex, ez = np.maximum(dc - 0.5, 0), np.maximum(dr - 0.5, 0)
        d[fr[a:a + 200], fc[a:a + 200]] = np.sqrt(ex ** 2 + ez ** 2).min(axis=1)
    return d


def local_pore_size(dist):
    """Local thickness of the pore space: for each fluid cell the diameter of the largest disc inside
    the fluid (centred on a fluid cell, radius its distance to the solid) that covers it."""
    n0, n1 = dist.shape
    size = np.zeros(dist.shape)
    rr, cc = np.mgrid[0:n0, 0:n1]
    for r, c in zip(*np.nonzero(dist > 0)):
        dr, dc = np.abs(rr - r), np.abs(cc - c)
        dr, dc = np.minimum(dr, n0 - dr), np.minimum(dc, n1 - dc)
        cover = dr * dr + dc * dc <= dist[r, c] ** 2
        size[cover] = np.maximum(size[cover], 2 * dist[r, c])
    return size


def runs(flags):
    """(start, length) of each run of True in a 1-D array, in order."""
    edges = np.flatnonzero(np.diff(np.concatenate([[0], flags.astype(int), [0]])))
    return [(a, b - a) for a, b in zip(edges[::2], edges[1::2])]


def open_band(solid):
    """The widest band of rows fluid at every column (a crack along x): (first row, last row) and per
    column the opening there (the run of fluid rows holding the band's centre). None without one."""
    bands = runs(~solid.any(axis=1))
    if not bands:
        return None
    first, length = max(bands, key=lambda band: band[1])
    centre = first + length // 2
    widths = [n for column in ~solid.T for a, n in runs(column) if a <= centre < a + n]
    return (first, first + length - 1), np.array(widths)


def middle_of_first_run(flags):
    """The middle index of the first run of True in a 1-D array."""
    a, n = runs(flags)[0]
    return a + (n - 1) // 2


def crack_in_box(solid, lo, hi):
    """open_band in the box's units (the mask covering [lo, hi] in x and z): the crack's band (lower z,
    upper z), its opening per column (pixels), and the x of its narrowest and of its widest column (the
    middle of the first run of each). None without a crack."""
    crack = open_band(solid)
    if crack is None:
        return None
    (first, last), widths = crack
    pixel = (hi - lo) / solid.shape[::-1]  # (x, z) size of a pixel
    band_z = lo[1] + first * pixel[1], lo[1] + (last + 1) * pixel[1]
    sections = [lo[0] + (middle_of_first_run(widths == w) + 0.5) * pixel[0] for w in (widths.min(), widths.max())]
    return band_z, widths, sections


def runs_along_band(start, end, band_z, lo, hi):
    """Whether the line from start to end (x, y, z) runs across the box [lo, hi] in x at one height z
    inside the band (lower z, upper z), strictly."""
    across = min(start[0], end[0]) <= lo[0] and max(start[0], end[0]) >= hi[0]
    return start[2] == end[2] and band_z[0] < start[2] < band_z[1] and across
