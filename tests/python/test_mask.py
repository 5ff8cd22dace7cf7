"""dpdfoam.mask on tiny synthetic images and masks with known regions.

A PNG written here reads back as its dark pixels (grey below 1/2), bottom row first as the solver
places it; a case's mask covers its builder's box in x and z and lands on a grid's bin centres pixel by
pixel. The distance to the solid is the analytic distance from a cell's centre to the nearest solid
cell's edge (a periodic band, a single solid pixel); the local pore size of a band of 7 fluid rows is 7
everywhere in it and 0 in the solid. The open band of a cracked mask, its opening per column, its
height in the box's units and the x of its narrowest and widest columns are the planted ones, and a
line runs along it only straight across the box strictly inside it.
A colour pixel's grey is the solver's luminance (geometry/GreyImage.cpp), and a case's mask is solid
where the case says (solidBelow, solidAbove, solidValues: geometry/GeometryDictionary.cpp).
"""
import math
import os
import unittest

import numpy as np
from matplotlib.image import imsave

from dpdfoam.mask import (case_mask, crack_in_box, distance_to_solid, local_pore_size, middle_of_first_run, on_grid,
                          open_band, read_image_mask, runs, runs_along_band)
from dpdtest_support import fake_dictionary, Temporary, write_text


def picture():
    """4 x 5 RGB picture, top row first: the top row black, one dark grey (0.3) and one light grey
    (0.7) pixel, the rest white."""
    rgb = np.ones((4, 5, 3))
    rgb[0] = 0.0
    rgb[2, 1] = 0.3
    rgb[1, 3] = 0.7
    return rgb


SOLID_OF_PICTURE = np.array([[0, 0, 0, 0, 0], [0, 1, 0, 0, 0], [0, 0, 0, 0, 0], [1, 1, 1, 1, 1]], dtype=bool)  # bottom first


class ReadImage(Temporary):
    def test_png(self):
        path = os.path.join(self.tmp, "mask.png")
        imsave(path, picture())
        np.testing.assert_array_equal(read_image_mask(path), SOLID_OF_PICTURE)

    def test_grey_png(self):
        path = os.path.join(self.tmp, "grey.png")
        imsave(path, picture()[..., 0], cmap="gray", vmin=0.0, vmax=1.0)
        np.testing.assert_array_equal(read_image_mask(path), SOLID_OF_PICTURE)

    def test_colour_pixel_grey_as_the_solver_weighs_it(self):
        # geometry/GreyImage.cpp reads a colour pixel's grey as the luminance 0.299 R + 0.587 G + 0.114 B:
        # a pure green pixel is fluid (0.587 >= 1/2), not solid as the plain mean of R, G, B (1/3) would say.
        rgb = np.ones((2, 2, 3))
        rgb[0, 0] = (0.0, 1.0, 0.0)
        path = os.path.join(self.tmp, "green.png")
        imsave(path, rgb)
        self.assertFalse(read_image_mask(path).any())

    def case(self, threshold_entry):
        """A case with the picture as its mask over the box x in [0, 10], z in [-2, 2]."""
        case = os.path.join(self.tmp, "case")
        os.makedirs(os.path.join(case, "constant", "geometry"))
        imsave(os.path.join(case, "constant", "geometry", "porous.png"), picture())
        props = write_text(os.path.join(case, "constant", "dpdProperties"),
                           f'geometry\n{{\n    type imageMask;\n    file "constant/geometry/porous.png";\n    {threshold_entry};\n'
                           "    pixelSize 2;\n}\n")
        builder = os.path.join(case, "system", "randomEquilWallDict")
        key, value = threshold_entry.split()
        entries = {(props, "geometry/file"): '"constant/geometry/porous.png"', (props, f"geometry/{key}"): value,
                   (props, "geometry/type"): "imageMask", (builder, "box/min"): "(0 -0.5 -2)", (builder, "box/max"): "(10 0.5 2)"}
        return case, entries

    def test_case_mask(self):
        case, entries = self.case("solidBelow 128")
        with fake_dictionary(self.tmp, entries):
            solid, path, lo, hi = case_mask(case)
        np.testing.assert_array_equal(solid, SOLID_OF_PICTURE)
        self.assertEqual(path, "constant/geometry/porous.png")
        np.testing.assert_array_equal(lo, [0.0, -2.0])
        np.testing.assert_array_equal(hi, [10.0, 2.0])

    def test_case_mask_with_bright_solid(self):
        # A case's imageMask says which pixels are solid (solidBelow, solidAbove or solidValues,
        # geometry/GeometryDictionary.cpp): `solidAbove 128` makes the bright pixels solid.
        case, entries = self.case("solidAbove 128")
        with fake_dictionary(self.tmp, entries):
            solid, _, _, _ = case_mask(case)
        np.testing.assert_array_equal(solid, ~SOLID_OF_PICTURE)

    def test_case_mask_with_solid_values(self):
        case, entries = self.case("solidValues (0)")  # only the black pixels (the top row)
        with fake_dictionary(self.tmp, entries):
            solid, _, _, _ = case_mask(case)
        expected = SOLID_OF_PICTURE.copy()
        expected[1, 1] = False  # the dark grey pixel is not level 0
        np.testing.assert_array_equal(solid, expected)

    def test_case_mask_without_a_rule_exits(self):
        case, entries = self.case("solidBelow 128")
        entries = {k: v for k, v in entries.items() if k[1] != "geometry/solidBelow"}
        with fake_dictionary(self.tmp, entries):
            with self.assertRaises(SystemExit):
                case_mask(case)

    def test_levels_against_the_rule(self):
        # An 8-bit grey image's levels compared as the solver compares them (geometry/ImageMask.cpp).
        from PIL import Image

        path = os.path.join(self.tmp, "levels.png")
        Image.fromarray(np.array([[0, 127, 128, 255]], dtype=np.uint8)).save(path)
        np.testing.assert_array_equal(read_image_mask(path), [[True, True, False, False]])
        np.testing.assert_array_equal(read_image_mask(path, ("solidBelow", 128.0)), [[True, True, False, False]])
        np.testing.assert_array_equal(read_image_mask(path, ("solidAbove", 127.0)), [[False, False, True, True]])
        np.testing.assert_array_equal(read_image_mask(path, ("solidValues", np.array([0.0, 128.0]))),
                                      [[True, False, True, False]])


class OnGrid(unittest.TestCase):
    def test_pixels_to_bins(self):
        solid = np.zeros((4, 8), dtype=bool)  # pixels of 2 x 2 over x in [0, 16], z in [-4, 4]
        solid[1, 2] = solid[3, 7] = True
        lo, hi = np.array([0.0, -4.0]), np.array([16.0, 4.0])
        coarse = on_grid(solid, lo, hi, np.arange(1.0, 16.0, 2.0), np.array([-3.0, -1.0, 1.0, 3.0]))
        np.testing.assert_array_equal(coarse, solid)
        fine = on_grid(solid, lo, hi, np.arange(0.5, 16.0, 1.0), np.arange(-3.5, 4.0, 1.0))
        np.testing.assert_array_equal(fine, np.kron(solid, np.ones((2, 2), dtype=bool)))


class Distances(unittest.TestCase):
    def test_band(self):
        solid = np.zeros((10, 6), dtype=bool)
        solid[:2] = True  # rows 0 and 1 solid; periodic, so rows 2..9 lie between row 1 and row 0 (10)
        d = distance_to_solid(solid)
        expected = np.array([0, 0] + [min(r - 1, 10 - r) - 0.5 for r in range(2, 10)])
        np.testing.assert_allclose(d, np.repeat(expected[:, None], 6, axis=1))

    def test_single_pixel(self):
        solid = np.zeros((20, 20), dtype=bool)
        solid[5, 5] = True
        d = distance_to_solid(solid)
        self.assertAlmostEqual(d[8, 9], math.hypot(2.5, 3.5), places=14)
        self.assertAlmostEqual(d[5, 7], 1.5, places=14)
        self.assertAlmostEqual(d[19, 5], 5.5, places=14)  # across the periodic edge: 6 rows away
        self.assertEqual(d[5, 5], 0.0)

    def test_pore_size_of_a_band(self):
        solid = np.zeros((12, 5), dtype=bool)
        solid[:5] = True  # 7 fluid rows, 5..11
        size = local_pore_size(distance_to_solid(solid))
        np.testing.assert_allclose(size[5:], 7.0)
        np.testing.assert_array_equal(size[:5], 0.0)


def cracked():
    """12 rows x 10 columns of solid (row 0 the bottom) with a crack along x in rows 5-6, wider at
    columns 3-4 (row 7 open too) and at column 8 (row 4), and a pocket in row 9 that does not cross."""
    solid = np.ones((12, 10), dtype=bool)
    solid[5:7] = False
    solid[7, 3:5] = False
    solid[4, 8] = False
    solid[9, 0:4] = False
    return solid


class Cracks(unittest.TestCase):
    def test_runs(self):
        self.assertEqual(runs(np.array([1, 1, 0, 1, 0, 0, 1, 1, 1], dtype=bool)), [(0, 2), (3, 1), (6, 3)])
        self.assertEqual(runs(np.zeros(4, dtype=bool)), [])
        self.assertEqual(middle_of_first_run(np.array([0, 1, 1, 1, 1, 0, 1], dtype=bool)), 2)

    def test_open_band(self):
        (first, last), widths = open_band(cracked())
        self.assertEqual((first, last), (5, 6))
        np.testing.assert_array_equal(widths, [2, 2, 2, 3, 3, 2, 2, 2, 3, 2])
        self.assertIsNone(open_band(np.ones((4, 4), dtype=bool)))

    def test_crack_in_box(self):
        lo, hi = np.array([0.0, -6.0]), np.array([20.0, 6.0])  # pixels 2 wide, 1 high
        band_z, widths, (narrowest, widest) = crack_in_box(cracked(), lo, hi)
        self.assertEqual(band_z, (-1.0, 1.0))
        self.assertEqual((narrowest, widest), (3.0, 7.0))  # columns 1 and 3, their centres
        self.assertIsNone(crack_in_box(np.ones((4, 4), dtype=bool), lo, hi))

    def test_runs_along_band(self):
        lo, hi, band = np.array([0.0, -6.0]), np.array([20.0, 6.0]), (-1.0, 1.0)
        self.assertTrue(runs_along_band((-1, 0, 0), (21, 0, 0), band, lo, hi))
        self.assertTrue(runs_along_band((20, 0, 0.5), (0, 0, 0.5), band, lo, hi))
        self.assertFalse(runs_along_band((-1, 0, 1.0), (21, 0, 1.0), band, lo, hi))  # on the band's edge
        self.assertFalse(runs_along_band((1, 0, 0), (21, 0, 0), band, lo, hi))  # not across the box
        self.assertFalse(runs_along_band((-1, 0, 0), (21, 0, 0.5), band, lo, hi))  # not at one height


if __name__ == "__main__":
    unittest.main()
