// The closed forms of analysis/StripedSlip.hpp: Philip, Belyaev-Vinogradova, the thin-channel limits
// (docs/analysis.md 5.1, "Closed forms").
#include "analysis/StripedSlip.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace dpd {

namespace {

constexpr double kPi = 3.14159265358979323846;

void checkStripes(double period, double slipFraction, double localSlip) {
    if (!(period > 0.0) || !(slipFraction >= 0.0 && slipFraction <= 1.0) || !(localSlip >= 0.0))
        throw std::invalid_argument("striped slip formula: needs L > 0, 0 <= phi2 <= 1, b >= 0");
}

// ln sec x and ln(sec x + tan x) at x = pi phi2 / 2: Philip's slip and Belyaev-Vinogradova's slip resistance.
double logSec(double slipFraction) { return -std::log(std::cos(0.5 * kPi * slipFraction)); }
double logSecPlusTan(double slipFraction) {
    const double x = 0.5 * kPi * slipFraction;
    return std::log((1.0 + std::sin(x)) / std::cos(x));
}

// Belyaev and Vinogradova's interpolation between Philip (b -> infinity) and the resistance of the gas sectors.
double belyaevVinogradova(double period, double slipFraction, double localSlip, double scale) {
    checkStripes(period, slipFraction, localSlip);
    if (slipFraction == 0.0 || localSlip == 0.0) return 0.0;
    if (slipFraction == 1.0) return localSlip;  // the formulas' limit, and the uniform wall's own slip
    const double philip = period / scale * logSec(slipFraction);
    if (std::isinf(localSlip)) return philip;
    return philip / (1.0 + period / (scale * localSlip) * logSecPlusTan(slipFraction));
}

// phi2 b H / (H + c phi1 b): lubrication over each stripe, the flux factor (H + 4b)/(H + b) or 1 + 6b/H
// averaged (c = 1 or 0, along the stripes) or its inverse averaged (c = 4 or 6, across them).
double thinChannel(const StripedWall& w, double c) {
    checkStripes(w.period, w.slipFraction, w.localSlip);
    if (!(w.height > 0.0) || std::isinf(w.height) || (w.stripedWalls != 1 && w.stripedWalls != 2))
        throw std::invalid_argument("thin-channel slip: needs a finite height H > 0 and 1 or 2 striped walls");
    const double phi1 = 1.0 - w.slipFraction;
    if (w.slipFraction == 0.0 || w.localSlip == 0.0) return 0.0;
    if (std::isinf(w.localSlip)) return w.slipFraction * w.height / (c * phi1);
    return w.slipFraction * w.localSlip * w.height / (w.height + c * phi1 * w.localSlip);
}

}  // namespace

double philipLongitudinalSlip(double period, double slipFraction) {
    checkStripes(period, slipFraction, 0.0);
    if (slipFraction == 1.0) return std::numeric_limits<double>::infinity();  // a shear-free wall
    return period / kPi * logSec(slipFraction);
}

double philipTransverseSlip(double period, double slipFraction) { return 0.5 * philipLongitudinalSlip(period, slipFraction); }

double belyaevVinogradovaLongitudinalSlip(double period, double slipFraction, double localSlip) {
    return belyaevVinogradova(period, slipFraction, localSlip, kPi);
}

double belyaevVinogradovaTransverseSlip(double period, double slipFraction, double localSlip) {
    return belyaevVinogradova(period, slipFraction, localSlip, 2.0 * kPi);
}

// c = 0 for two striped walls in phase: their flux factor 1 + 6b/H is linear in b, so its mean is phi2 b.
double thinChannelLongitudinalSlip(const StripedWall& wall) { return thinChannel(wall, wall.stripedWalls == 2 ? 0.0 : 1.0); }

double thinChannelTransverseSlip(const StripedWall& wall) { return thinChannel(wall, wall.stripedWalls == 2 ? 6.0 : 4.0); }

}  // namespace dpd
