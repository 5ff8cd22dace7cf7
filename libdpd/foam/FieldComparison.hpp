#pragma once
// DPD against the continuum on the same points (METHODS.md 5, continuum comparison). The finite-volume
// solution is brought to the DPD bin centres (interpolated), never the other way round, so each DPD
// value keeps its own error bar.
//
//   L2                 sqrt( sum (u_DPD - u_FVM)^2 / sum u_FVM^2 )
//   Linf               max |u_DPD - u_FVM| / max |u_FVM|
//   meanVelocityRatio  mean u_DPD / mean u_FVM (equal bins: the ratio of the flow rates)
//   noiseL2            sqrt( sum err_DPD^2 / sum u_FVM^2 ): the L2 that the DPD noise alone gives on
//                      average (E[(u_DPD - u)^2] = err^2 when u_FVM is the truth), the scale a
//                      tolerance on L2 is set against
#include <Eigen/Core>

#include <vector>

namespace dpd {

struct ComparisonMetrics {
    int points = 0;
    double L2 = 0.0;
    double Linf = 0.0;
    double noiseL2 = 0.0;
    double meanDPD = 0.0;
    double meanFVM = 0.0;
    double meanVelocityRatio = 0.0;
};

// The metrics over the points where fvm is finite (NaN marks points outside the continuum's domain).
// std::invalid_argument when the arrays differ in length (dpdErr may be empty: no error bars), or when
// fewer than one point is usable or the FVM values are all zero.
ComparisonMetrics compareValues(const std::vector<double>& dpd, const std::vector<double>& dpdErr,
                                const std::vector<double>& fvm);

// Piecewise-linear interpolation of v(x), x increasing; NaN outside [x.front(), x.back()].
double interpolateLinear(const std::vector<double>& x, const std::vector<double>& v, double at);

// A cell field reduced to a profile along one axis: the mean of one velocity component over the cells
// of each layer (cells whose centres share the coordinate along the axis to within `tolerance`),
// fluid cells only as the DPD bins average over fluid particles only. Layers in increasing order.
struct LayerProfile {
    std::vector<double> x;
    std::vector<double> u;
};
LayerProfile layerAverage(const std::vector<Eigen::Vector3d>& centres, const std::vector<Eigen::Vector3d>& U,
                          int axis, int component, double tolerance);

// The layer profile continued linearly from its two outermost layers out to lo and hi (the walls): the
// half cell between a wall and the first cell centre, where the DPD bins next to the wall lie.
LayerProfile extendToBounds(const LayerProfile& p, double lo, double hi);

}  // namespace dpd
