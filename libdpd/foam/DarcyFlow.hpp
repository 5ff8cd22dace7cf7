#pragma once
// Darcy's law for a porous medium driven by a body force g per unit mass (docs/scenes.md scene 6):
//
//   u_s = (k / nu) g,   so   k = nu u_s / g
//
// with u_s the superficial velocity: the flux per unit area of the whole medium, solid included (the
// volume average of the velocity with zero in the solid), and k the permeability (an area; r_c^2 here).
// Each side's u_s is taken over the same rectangle, the grid of the DPD bins:
//  - finite volumes (a uniform mesh, solid cells cut out): the sum of the cells' velocities over the
//    number of cells the rectangle held before the cut; the porosity is the fraction of cells left;
//  - DPD bins: the mean over all bins of density x velocity, over the fluid's number density (the
//    density the box was filled at): the fluid's momentum per unit volume over its mass per unit volume.
//    The porosity is the mean density over the fluid density. The error of u_s treats the bins as
//    independent (their velocity error bars come from block averages, each bin's own).
#include "foam/FieldComparison.hpp"

#include <vector>

namespace dpd {

struct DarcyFlow {
    double porosity = 0.0;
    double superficialVelocity = 0.0;
    double superficialVelocityErr = 0.0;
    double permeability = 0.0;
    double permeabilityErr = 0.0;
};

// g: the body force's component along the compared velocity (either sign).
// cellsPerBin: how many mesh cells (before the solid was cut) one bin holds. std::invalid_argument when
// cellsPerBin or nu is not positive, or g is zero.
DarcyFlow darcyFromCells(const BinnedCells& cells, double cellsPerBin, double nu, double g);

// One entry per bin of the whole grid (empty bins: density 0). std::invalid_argument for unequal
// lengths (uErr may be empty), a fluid density or nu that is not positive, or g zero.
DarcyFlow darcyFromBins(const std::vector<double>& density, const std::vector<double>& u, const std::vector<double>& uErr,
                        double fluidDensity, double nu, double g);

}  // namespace dpd
