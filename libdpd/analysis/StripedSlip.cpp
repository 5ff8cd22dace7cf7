#include "analysis/StripedSlip.hpp"

#include "analysis/StripedSlipGalerkin.hpp"
#include "analysis/StripedSlipModes.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dpd {

namespace {

constexpr double kPi = 3.14159265358979323846;

void checkWall(const StripedWall& w) {
    if (!(w.period > 0.0) || !std::isfinite(w.period))
        throw std::invalid_argument("striped wall: the period L must be positive and finite");
    if (!(w.slipFraction >= 0.0 && w.slipFraction <= 1.0))
        throw std::invalid_argument("striped wall: the slip fraction phi2 must lie in [0, 1]");
    if (!(w.localSlip >= 0.0)) throw std::invalid_argument("striped wall: the local slip b must be >= 0");
    if (!(w.height > 0.0)) throw std::invalid_argument("striped wall: the height H must be positive");
    if (w.stripedWalls != 1 && w.stripedWalls != 2)
        throw std::invalid_argument("striped wall: stripedWalls must be 1 or 2");
    if (w.stripedWalls == 2 && std::isinf(w.height))
        throw std::invalid_argument("striped wall: two striped walls need a finite channel height");
}

// The uniform slip length whose channel passes `factor` times the no-slip flux (channelFluxFactor inverted).
double slipFromFluxFactor(double factor, double height, int stripedWalls) {
    if (stripedWalls == 2) return (factor - 1.0) * height / 6.0;
    return height * (factor - 1.0) / (4.0 - factor);
}

// The mean flow's share of the wall problem (docs/analysis.md 5.1, "The mean flow and one mode"):
// u = y + a0 under unit shear; u = y (H - y) / 2 + a0 (1 - y / H) against a no-slip wall;
// u = y (H - y) / 2 + a0 between two striped walls, all with unit pressure gradient over viscosity.
StripedWallProblem wallProblem(const StripedWall& w, StripedFlow flow) {
    StripedWallProblem p;
    p.period = w.period;
    p.slipFraction = w.slipFraction;
    p.inverseSlip = std::isinf(w.localSlip) ? 0.0 : 1.0 / w.localSlip;
    const bool channel = std::isfinite(w.height);
    p.meanShear = channel ? 0.5 * w.height : 1.0;
    p.meanShearPerSlip = channel && w.stripedWalls == 1 ? 1.0 / w.height : 0.0;
    const double height = w.height;
    const int walls = w.stripedWalls;
    p.response = [flow, height, walls](double k) { return stripedModeResponse(flow, k, height, walls); };
    p.responseSlope = stripedModeResponseSlope(flow);
    return p;
}

// b_eff from the mean slip velocity: a0 itself under unit shear, else through the flux
// Q = H^3/12 + a0 H / 2 (one striped wall) or H^3/12 + a0 H (two).
double slipFromMeanSlipVelocity(const StripedWall& w, double a0) {
    if (std::isinf(w.height)) return a0;
    const double perWall = w.stripedWalls == 1 ? 6.0 : 12.0;
    return slipFromFluxFactor(1.0 + perWall * a0 / (w.height * w.height), w.height, w.stripedWalls);
}

// theta_c = pi phi2, kept off zero for the resolution's sake.
double sectorAngle(const StripedWall& w) { return kPi * std::max(w.slipFraction, 1e-12); }

// The tail asymptote holds once n theta_c >> basis^2, n sin(theta_c) >> 1 (the edges' square roots are
// resolved) and, in a channel, once e^(-kH) is negligible.
int modesFor(const StripedWall& w, int basis) {
    const double thetaC = sectorAngle(w);
    double modes = std::max({512.0, 4.0 * basis * basis / thetaC, 32.0 / std::sin(thetaC)});
    if (std::isfinite(w.height)) modes = std::max(modes, 8.0 * w.period / w.height);
    // The work, modes x nodes x basis with nodes = 0.6 modes theta_c + 2 basis + 64, kept below 1e9
    // (about 0.1 s): reached only with phi2 within about 1e-3 of 1, or b or H below about 1e-3 L.
    const double a = 0.6 * thetaC, c = 2.0 * basis + 64.0, budget = 1e9 / basis;
    modes = std::min(modes, (std::sqrt(c * c + 4.0 * a * budget) - c) / (2.0 * a));
    return static_cast<int>(std::ceil(modes));
}

double solveSlip(const StripedWall& w, StripedSlipResolution r, StripedFlow flow) {
    checkWall(w);
    if (w.slipFraction == 0.0 || w.localSlip == 0.0) return 0.0;
    if (w.slipFraction == 1.0) return w.localSlip;  // a uniform wall is its own reference
    const int basis = r.basis > 0 ? r.basis : stripedSlipResolution(w).basis;
    const int modes = r.modes > 0 ? r.modes : modesFor(w, basis);
    return slipFromMeanSlipVelocity(w, meanSlipVelocity(wallProblem(w, flow), basis, modes));
}

}  // namespace

StripedSlipResolution stripedSlipResolution(const StripedWall& w) {
    checkWall(w);
    // The sector functions resolve theta_c / basis^2 next to an edge, where the finest lengths are b
    // (below it a gas sector looks shear-free), H and the no-slip strip phi1 L (measured: the last two
    // need the larger factor). A narrow sector needs few functions.
    const double k = 2.0 * kPi / w.period;
    const double thetaC = sectorAngle(w);
    const double geometric = std::min(w.height, (1.0 - w.slipFraction) * w.period);
    StripedSlipResolution r;
    r.basis = w.slipFraction < 0.05 ? 4 : 8;
    if (std::isfinite(w.localSlip))
        r.basis = std::max(r.basis, static_cast<int>(std::ceil(1.5 * std::sqrt(thetaC / (k * w.localSlip)))));
    if (std::isfinite(geometric) && geometric > 0.0)
        r.basis = std::max(r.basis, static_cast<int>(std::ceil(2.5 * std::sqrt(thetaC / (k * geometric)))));
    r.basis = std::min(r.basis, 48);
    r.modes = modesFor(w, r.basis);
    return r;
}

double longitudinalSlip(const StripedWall& wall, StripedSlipResolution resolution) {
    return solveSlip(wall, resolution, StripedFlow::longitudinal);
}

double transverseSlip(const StripedWall& wall, StripedSlipResolution resolution) {
    return solveSlip(wall, resolution, StripedFlow::transverse);
}

SlipTensor stripedSlipTensor(const StripedWall& wall, StripedSlipResolution resolution) {
    return {longitudinalSlip(wall, resolution), transverseSlip(wall, resolution)};
}

double effectiveSlip(const SlipTensor& slip, double theta) {
    const double c = std::cos(theta), s = std::sin(theta);
    return slip.parallel * c * c + slip.perpendicular * s * s;
}

double channelFluxFactor(double slip, double height, int stripedWalls) {
    if (!(height > 0.0) || std::isinf(height) || !(slip >= 0.0) || (stripedWalls != 1 && stripedWalls != 2))
        throw std::invalid_argument("channelFluxFactor: needs 0 < H finite, slip >= 0, 1 or 2 striped walls");
    if (stripedWalls == 2) return 1.0 + 6.0 * slip / height;
    if (std::isinf(slip)) return 4.0;
    return (height + 4.0 * slip) / (height + slip);
}

double transverseFluxRatio(const SlipTensor& slip, double height, int stripedWalls, double theta) {
    const double parallel = channelFluxFactor(slip.parallel, height, stripedWalls);
    const double perpendicular = channelFluxFactor(slip.perpendicular, height, stripedWalls);
    // Q_perp / Q_par, 1 when both are infinite (a uniformly shear-free channel is isotropic).
    const double ratio = std::isinf(parallel) ? (std::isinf(perpendicular) ? 1.0 : 0.0) : perpendicular / parallel;
    const double c = std::cos(theta), s = std::sin(theta);
    return (1.0 - ratio) * s * c / (c * c + ratio * s * s);
}

double transverseFluxRatio(const StripedWall& wall, double theta, StripedSlipResolution resolution) {
    checkWall(wall);
    if (std::isinf(wall.height)) throw std::invalid_argument("transverseFluxRatio: needs a channel (finite H)");
    return transverseFluxRatio(stripedSlipTensor(wall, resolution), wall.height, wall.stripedWalls, theta);
}

}  // namespace dpd
