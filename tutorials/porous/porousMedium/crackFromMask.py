#!/usr/bin/env python3
"""The porous medium's crack from its mask, for a mask of one's own (Allrun, before the runs).

Reads the mask (constant/dpdProperties geometry/file) over the box it covers (system/randomEquilWallDict)
and finds its crack: the band of pixel rows that are fluid at every x (makePorousMask.py's crack runs
along the flow, x). When the case's line `crack` (system/makeFoamCaseDict, which makeFoamCase samples
and compareFVM compares) does not run across the box inside that band, the case was set up for another
mask: the line is moved to the band's centre (across the box, four points per cutoff) and the sections of
flowField (system/controlDict) to the crack's narrowest and widest columns; the dictionaries are kept as
*.orig (Allclean puts them back). The tutorial's own masks leave the case as it is. A mask without such a
band leaves it too, and says so: plotResults.py then compares the lines the case names.
"""
import sys

from dpdfoam.io import case_line, set_case_line, set_dictionary_value, vector_text
from dpdfoam.mask import case_mask, crack_in_box, runs_along_band


def main():
    solid, mask, lo, hi = case_mask()
    crack = crack_in_box(solid, lo, hi)
    if crack is None:
        print(f"crackFromMask: {mask} has no crack (no row fluid across the box): the case's lines are kept")
        return 0
    band_z, widths, sections = crack
    print(f"crackFromMask: {mask}: crack band z {band_z[0]:g} to {band_z[1]:g}, width {widths.min()}-{widths.max()} pixels")
    line = case_line("crack")  # the line makeFoamCase samples and compareFVM compares
    if line is not None and runs_along_band(*line, band_z, lo, hi):
        print("crackFromMask: the case's crack line runs along it: the case is kept as it is")
        return 0
    z = 0.5 * (band_z[0] + band_z[1])
    set_case_line("crack", (lo[0], 0, z), (hi[0], 0, z), int(round(4 * (hi[0] - lo[0]))) + 1)
    set_dictionary_value("system/controlDict", "functions/flowField/sections", vector_text(sections))
    print(f"crackFromMask: the crack line set at z = {z:g} from x = {lo[0]:g} to {hi[0]:g}; sections at the narrowest "
          f"and widest columns, x = {sections[0]:g} and {sections[1]:g}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
