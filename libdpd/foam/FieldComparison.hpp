#pragma once
// DPD against the continuum on the same points (docs/analysis.md 5, continuum comparison). The finite-volume
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

// A regular 2-D grid of bins over two box axes (a 2-D DPD profile's): bin (i, j) is entry i + n0 j.
struct BinGrid {
    int axis0 = 0, axis1 = 2;
    int n0 = 1, n1 = 1;
    double lo0 = 0.0, hi0 = 1.0, lo1 = 0.0, hi1 = 1.0;
    std::size_t size() const { return static_cast<std::size_t>(n0) * static_cast<std::size_t>(n1); }
    double width0() const { return (hi0 - lo0) / n0; }
    double width1() const { return (hi1 - lo1) / n1; }
    // The bin holding the point (a along axis0, b along axis1); -1 outside the grid.
    long index(double a, double b) const;
};

// The grid of a table's bin centres (first coordinate fastest, as profileBins writes them):
// std::invalid_argument when they do not form a regular grid in that order.
BinGrid gridOfCentres(int axis0, int axis1, const std::vector<double>& c0, const std::vector<double>& c1);

// The cells of a finite-volume field gathered into the bins of a grid: per bin the sum of one velocity
// component over the cells whose centres lie in it, and their number. On a mesh finer than the bins
// the mean (sum / cells) is the continuum's average over the bin's fluid, the quantity a DPD bin
// measures (the mean over the fluid particles in it); a bin with no fluid cell has no value.
struct BinnedCells {
    std::vector<double> sum;
    std::vector<long> cells;
    double mean(std::size_t bin) const;   // NaN when the bin holds no cell
};
BinnedCells binCells(const std::vector<Eigen::Vector3d>& centres, const std::vector<Eigen::Vector3d>& U,
                     int component, const BinGrid& grid);

// Piecewise-linear interpolation of samples v(x), x increasing, that may have gaps (a sampled line
// crossing solid, where OpenFOAM writes no point): NaN where the two samples around `at` are more than
// maxGap apart, or outside.
double interpolateAcrossSamples(const std::vector<double>& x, const std::vector<double>& v, double at, double maxGap);

// The layer profile continued linearly from its two outermost layers out to lo and hi (the walls): the
// half cell between a wall and the first cell centre, where the DPD bins next to the wall lie.
LayerProfile extendToBounds(const LayerProfile& p, double lo, double hi);

}  // namespace dpd
