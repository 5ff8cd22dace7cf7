#pragma once
// A velocity profile across a channel, as the fits take it: the bins' centres, mean velocities and
// standard errors, and optionally the same profile measured in each independent block of the run.
//
// Why the blocks: the bins of a flow profile do not fluctuate independently. The channel's slowest
// flow mode moves every bin together (the flow rate wanders), so a fit that weighs the bins as
// independent quotes errors several times too small for what depends on the level of the profile (the
// slip velocity and slip length; docs/analysis.md section 5.2). With the blocks, the fit is applied
// to each block and the errors come from the spread of the block coefficients (WeightedPolyFit.hpp).
#include "analysis/WeightedPolyFit.hpp"

#include <functional>
#include <vector>

namespace dpd {

struct Profile1D {
    std::vector<double> y;     // bin centres (wall-normal coordinate)
    std::vector<double> u;     // mean velocity along the flow
    std::vector<double> uErr;  // its standard error; empty or all zero = unknown (unit weights)
    // Optional: blocks[k][i] is point i's mean velocity in block k, blocks in time order (correlations
    // between neighbouring blocks are measured). Empty: the points are taken as independent.
    std::vector<std::vector<double>> blocks;
};

// The points (with their block values) whose mapped coordinate passes `keep`; y is replaced by the
// mapped coordinate (identity, or a periodic wrap).
Profile1D selectProfilePoints(const Profile1D& p, const std::function<double(double)>& coordinate,
                              const std::function<bool(double)>& keep);

// A polynomial fitted to the profile with weights 1 / uErr^2. Without blocks the covariance is scaled by
// chi^2/dof (WeightedPolyFit.hpp); with blocks it is the covariance of the blocks' coefficients' mean,
// multiplied by chi^2/dof only where that exceeds 1.
PolyFitResult fitProfilePolynomial(const Profile1D& p, int degree);

}  // namespace dpd
