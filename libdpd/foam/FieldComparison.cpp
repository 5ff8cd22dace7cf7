#include "foam/FieldComparison.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

namespace dpd {

ComparisonMetrics compareValues(const std::vector<double>& dpd, const std::vector<double>& dpdErr,
                                const std::vector<double>& fvm) {
    if (dpd.size() != fvm.size() || (!dpdErr.empty() && dpdErr.size() != dpd.size()))
        throw std::invalid_argument("compareValues: the DPD and FVM arrays differ in length");
    ComparisonMetrics m;
    double diff2 = 0.0, ref2 = 0.0, err2 = 0.0, maxDiff = 0.0, maxRef = 0.0, sumD = 0.0, sumF = 0.0;
    for (std::size_t i = 0; i < dpd.size(); ++i) {
        if (!std::isfinite(fvm[i])) continue;
        const double d = dpd[i] - fvm[i];
        diff2 += d * d;
        ref2 += fvm[i] * fvm[i];
        if (!dpdErr.empty()) err2 += dpdErr[i] * dpdErr[i];
        maxDiff = std::max(maxDiff, std::abs(d));
        maxRef = std::max(maxRef, std::abs(fvm[i]));
        sumD += dpd[i];
        sumF += fvm[i];
        ++m.points;
    }
    if (m.points == 0) throw std::invalid_argument("no DPD point lies inside the continuum's domain");
    if (!(ref2 > 0.0)) throw std::invalid_argument("the FVM velocity is zero at every compared point");
    m.L2 = std::sqrt(diff2 / ref2);
    m.Linf = maxDiff / maxRef;
    m.noiseL2 = std::sqrt(err2 / ref2);
    m.meanDPD = sumD / m.points;
    m.meanFVM = sumF / m.points;
    m.meanVelocityRatio = sumF != 0.0 ? sumD / sumF : std::numeric_limits<double>::quiet_NaN();
    return m;
}

double interpolateLinear(const std::vector<double>& x, const std::vector<double>& v, double at) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    if (x.empty() || at < x.front() || at > x.back()) return nan;
    if (x.size() == 1) return v.front();
    const auto hi = std::upper_bound(x.begin(), x.end(), at);
    const std::size_t k = hi == x.end() ? x.size() - 1 : static_cast<std::size_t>(hi - x.begin());
    const std::size_t j = k - 1;
    const double w = (at - x[j]) / (x[k] - x[j]);
    return (1.0 - w) * v[j] + w * v[k];
}

LayerProfile layerAverage(const std::vector<Eigen::Vector3d>& centres, const std::vector<Eigen::Vector3d>& U,
                          int axis, int component, double tolerance) {
    if (centres.size() != U.size())
        throw std::invalid_argument("layerAverage: " + std::to_string(centres.size()) + " cell centres but " +
                                    std::to_string(U.size()) + " velocities");
    // Layers keyed by the distance from the lowest centre in units of the tolerance: cells of one layer
    // differ by round-off only, so the key is an integer plus round-off, far from a rounding boundary.
    double lowest = 0.0;
    for (std::size_t c = 0; c < centres.size(); ++c) lowest = c == 0 ? centres[c][axis] : std::min(lowest, centres[c][axis]);
    std::map<long long, std::pair<double, std::pair<double, long>>> layers;  // key -> (x, (sum u, count))
    for (std::size_t c = 0; c < centres.size(); ++c) {
        const double x = centres[c][axis];
        auto& layer = layers[std::llround((x - lowest) / tolerance)];
        layer.first = x;
        layer.second.first += U[c][component];
        layer.second.second += 1;
    }
    LayerProfile p;
    for (const auto& [key, layer] : layers) {
        p.x.push_back(layer.first);
        p.u.push_back(layer.second.first / static_cast<double>(layer.second.second));
    }
    return p;
}

long BinGrid::index(double a, double b) const {
    const double fa = (a - lo0) / width0(), fb = (b - lo1) / width1();
    if (!(fa >= 0.0 && fa < n0 && fb >= 0.0 && fb < n1)) return -1;
    return static_cast<long>(fa) + static_cast<long>(n0) * static_cast<long>(fb);
}

BinGrid gridOfCentres(int axis0, int axis1, const std::vector<double>& c0, const std::vector<double>& c1) {
    if (c0.size() != c1.size() || c0.empty()) throw std::invalid_argument("the bin centre columns differ in length or are empty");
    BinGrid g;
    g.axis0 = axis0;
    g.axis1 = axis1;
    // The first coordinate runs fastest: n0 is the length of the first run of equal second coordinates.
    std::size_t n0 = 1;
    while (n0 < c1.size() && c1[n0] == c1[0]) ++n0;
    if (c0.size() % n0 != 0) throw std::invalid_argument("the bin centres do not form a grid (rows of unequal length)");
    g.n0 = static_cast<int>(n0);
    g.n1 = static_cast<int>(c0.size() / n0);
    const double w0 = n0 > 1 ? c0[1] - c0[0] : 1.0;
    const double w1 = g.n1 > 1 ? c1[n0] - c1[0] : 1.0;
    if (!(w0 > 0.0) || !(w1 > 0.0)) throw std::invalid_argument("the bin centres do not increase along the grid");
    g.lo0 = c0[0] - 0.5 * w0;
    g.hi0 = g.lo0 + g.n0 * w0;
    g.lo1 = c1[0] - 0.5 * w1;
    g.hi1 = g.lo1 + g.n1 * w1;
    const double tol = 1e-6;
    for (std::size_t k = 0; k < c0.size(); ++k) {
        const std::size_t i = k % n0, j = k / n0;
        if (std::abs(c0[k] - (g.lo0 + (i + 0.5) * w0)) > tol * w0 || std::abs(c1[k] - (g.lo1 + (j + 0.5) * w1)) > tol * w1)
            throw std::invalid_argument("the bin centres do not form a regular grid, first axis fastest (row " +
                                        std::to_string(k + 1) + ")");
    }
    return g;
}

double BinnedCells::mean(std::size_t bin) const {
    return cells[bin] > 0 ? sum[bin] / static_cast<double>(cells[bin]) : std::numeric_limits<double>::quiet_NaN();
}

BinnedCells binCells(const std::vector<Eigen::Vector3d>& centres, const std::vector<Eigen::Vector3d>& U,
                     int component, const BinGrid& grid) {
    if (centres.size() != U.size())
        throw std::invalid_argument("binCells: " + std::to_string(centres.size()) + " cell centres but " +
                                    std::to_string(U.size()) + " velocities");
    BinnedCells b;
    b.sum.assign(grid.size(), 0.0);
    b.cells.assign(grid.size(), 0);
    for (std::size_t c = 0; c < centres.size(); ++c) {
        const long k = grid.index(centres[c][grid.axis0], centres[c][grid.axis1]);
        if (k < 0) continue;
        b.sum[static_cast<std::size_t>(k)] += U[c][component];
        ++b.cells[static_cast<std::size_t>(k)];
    }
    return b;
}

double interpolateAcrossSamples(const std::vector<double>& x, const std::vector<double>& v, double at, double maxGap) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    if (x.empty() || at < x.front() || at > x.back()) return nan;
    if (x.size() == 1) return v.front();
    const auto hi = std::upper_bound(x.begin(), x.end(), at);
    const std::size_t k = hi == x.end() ? x.size() - 1 : static_cast<std::size_t>(hi - x.begin());
    return x[k] - x[k - 1] > maxGap ? nan : interpolateLinear(x, v, at);
}

LayerProfile extendToBounds(const LayerProfile& p, double lo, double hi) {
    if (p.x.size() < 2) return p;
    LayerProfile e;
    const std::size_t n = p.x.size();
    const auto line = [&](std::size_t a, std::size_t b, double at) {
        return p.u[a] + (p.u[b] - p.u[a]) * (at - p.x[a]) / (p.x[b] - p.x[a]);
    };
    if (lo < p.x.front()) {
        e.x.push_back(lo);
        e.u.push_back(line(0, 1, lo));
    }
    e.x.insert(e.x.end(), p.x.begin(), p.x.end());
    e.u.insert(e.u.end(), p.u.begin(), p.u.end());
    if (hi > p.x.back()) {
        e.x.push_back(hi);
        e.u.push_back(line(n - 2, n - 1, hi));
    }
    return e;
}

}  // namespace dpd
