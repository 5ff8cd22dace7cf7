#include "analysis/StripedSlipModes.hpp"

#include <cmath>

namespace dpd {

namespace {

// sum_{m >= first} x^(2m + odd) / (2m + odd)!: the tails of cosh (odd 0) and sinh (odd 1) without
// the cancellation of cosh x - 1 - ... at small x; 30 terms reach rounding for |x| < 2.
double hyperbolicTail(double x, int first, int odd) {
    double term = 1.0;
    const int lowest = 2 * first + odd;
    for (int i = 1; i <= lowest; ++i) term *= x / i;
    double sum = 0.0;
    for (int i = lowest; i < lowest + 60 && term != 0.0; i += 2) {
        sum += term;
        term *= x * x / ((i + 1.0) * (i + 2.0));
    }
    return sum;
}

// (sinh h cosh h - h) / (sinh^2 h - h^2): one striped wall facing a no-slip wall. Series below h = 1,
// where numerator and denominator are O(h^3) and O(h^4); scaled by 4 e^(-2h) above it, against overflow.
double oneWallTransverseRatio(double h) {
    if (h < 1.0) return hyperbolicTail(2.0 * h, 1, 1) / hyperbolicTail(2.0 * h, 2, 0);
    const double e = std::exp(-2.0 * h);
    return (1.0 - e * e - 4.0 * h * e) / (1.0 - 2.0 * e + e * e - 4.0 * h * h * e);
}

// (cosh h - 1) / (sinh h - h): two striped walls in phase, the stream function odd about y = H/2.
double twoWallTransverseRatio(double h) {
    if (h < 1.0) return hyperbolicTail(h, 1, 0) / hyperbolicTail(h, 1, 1);
    const double e = std::exp(-h);
    return (1.0 + e * e - 2.0 * e) / (1.0 - e * e - 2.0 * h * e);
}

// w = cosh(k(y - H/2)) / cosh(kH/2) (mirror plane), sinh(k(H - y)) / sinh(kH) (no-slip wall), e^(-ky).
double longitudinalResponse(double k, double height, int stripedWalls) {
    if (std::isinf(height)) return k;
    if (stripedWalls == 2) return k * std::tanh(0.5 * k * height);
    return k / std::tanh(k * height);
}

// psi = y e^(-ky) for a single wall; the channel forms are solved in docs/analysis.md 5.1.
double transverseResponse(double k, double height, int stripedWalls) {
    if (std::isinf(height)) return 2.0 * k;
    if (stripedWalls == 2) return 2.0 * k * twoWallTransverseRatio(k * height);
    return 2.0 * k * oneWallTransverseRatio(k * height);
}

}  // namespace

double stripedModeResponse(StripedFlow flow, double k, double height, int stripedWalls) {
    return flow == StripedFlow::longitudinal ? longitudinalResponse(k, height, stripedWalls)
                                             : transverseResponse(k, height, stripedWalls);
}

double stripedModeResponseSlope(StripedFlow flow) { return flow == StripedFlow::longitudinal ? 1.0 : 2.0; }

}  // namespace dpd
