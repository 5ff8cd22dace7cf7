#include "analysis/HydrodynamicWall.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace dpd {

namespace {

// A = h + b and B = h^2 + 2 b h with their errors, one per setting.
struct ReachAndZero {
    std::vector<double> a, aErr, b, bErr;
};

ReachAndZero reachAndZero(double width, const std::vector<ApparentSlip>& settings) {
    ReachAndZero r;
    const double half = 0.5 * width;
    for (const ApparentSlip& s : settings) {
        r.a.push_back(half + s.couette);
        r.aErr.push_back(s.couetteErr);
        r.b.push_back(half * half + width * s.poiseuille);
        r.bErr.push_back(width * s.poiseuilleErr);
    }
    return r;
}

// chi^2 of B_i = 2 h A_i - h^2 at h, each residual weighted by its variance there (A's error enters
// through dB/dA = 2 h).
double chi2(const ReachAndZero& r, double h) {
    double sum = 0.0;
    for (std::size_t i = 0; i < r.a.size(); ++i) {
        const double residual = r.b[i] - 2.0 * h * r.a[i] + h * h;
        const double variance = r.bErr[i] * r.bErr[i] + 4.0 * h * h * r.aErr[i] * r.aErr[i];
        sum += residual * residual / variance;
    }
    return sum;
}

// The h of least chi^2 in (0, 2 max A]: a grid for the basin (chi^2 need not be convex far from it),
// then golden section to rounding.
double bestHalfWidth(const ReachAndZero& r) {
    const double top = 2.0 * *std::max_element(r.a.begin(), r.a.end());
    const int n = 400;
    int best = 1;
    double bestChi2 = chi2(r, top / n);
    for (int k = 2; k <= n; ++k) {
        const double c = chi2(r, top * k / n);
        if (c < bestChi2) { best = k; bestChi2 = c; }
    }
    double lo = top * std::max(best - 1, 0) / n, hi = top * std::min(best + 1, n) / n;
    const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
    double x1 = hi - golden * (hi - lo), x2 = lo + golden * (hi - lo);
    double f1 = chi2(r, x1), f2 = chi2(r, x2);
    for (int it = 0; it < 200 && hi - lo > 1e-14 * top; ++it) {
        if (f1 < f2) {
            hi = x2; x2 = x1; f2 = f1;
            x1 = hi - golden * (hi - lo); f1 = chi2(r, x1);
        } else {
            lo = x1; x1 = x2; f1 = f2;
            x2 = lo + golden * (hi - lo); f2 = chi2(r, x2);
        }
    }
    return 0.5 * (lo + hi);
}

void checkSettings(double width, const std::vector<ApparentSlip>& settings) {
    if (!(width > 0.0) || !std::isfinite(width)) throw std::invalid_argument("the channel width must be positive");
    if (settings.size() < 2)
        throw std::invalid_argument("the hydrodynamic wall needs at least two wall settings (it is fitted across them)");
    double lo = settings[0].couette, hi = lo, largestErr = 0.0;
    for (std::size_t i = 0; i < settings.size(); ++i) {
        const ApparentSlip& s = settings[i];
        for (double v : {s.couette, s.poiseuille, s.couetteErr, s.poiseuilleErr})
            if (!std::isfinite(v)) throw std::invalid_argument("setting " + std::to_string(i) + ": a value is not finite");
        if (!(s.couetteErr > 0.0) || !(s.poiseuilleErr > 0.0))
            throw std::invalid_argument("setting " + std::to_string(i) + ": errors must be positive");
        lo = std::min(lo, s.couette);
        hi = std::max(hi, s.couette);
        largestErr = std::max(largestErr, s.couetteErr);
    }
    if (hi - lo <= 3.0 * largestErr)
        throw std::invalid_argument("the settings' Couette slip lengths differ by no more than 3 of their errors: "
                                    "no leverage on the wall's position");
}

}  // namespace

HydrodynamicWallFit fitHydrodynamicWall(double width, const std::vector<ApparentSlip>& settings) {
    checkSettings(width, settings);
    ReachAndZero r = reachAndZero(width, settings);
    const std::size_t n = settings.size();
    HydrodynamicWallFit fit;
    fit.halfWidth = bestHalfWidth(r);
    fit.offset = 0.5 * width - fit.halfWidth;
    fit.dof = static_cast<int>(n) - 1;
    fit.chi2PerDof = chi2(r, fit.halfWidth) / fit.dof;

    // Errors by the delta method: h's derivative by each input (central differences, steps a small
    // fraction of the input's error), then b_i = A_i - h. Scaled up when the settings scatter about
    // one h by more than their errors allow (not down: a few settings cannot vouch for smaller ones).
    std::vector<double> dhdA(n), dhdB(n);
    for (std::size_t j = 0; j < n; ++j) {
        for (int which = 0; which < 2; ++which) {
            std::vector<double>& x = which == 0 ? r.a : r.b;
            const double step = 1e-3 * (which == 0 ? r.aErr[j] : r.bErr[j]);
            const double keep = x[j];
            x[j] = keep + step;
            const double up = bestHalfWidth(r);
            x[j] = keep - step;
            const double down = bestHalfWidth(r);
            x[j] = keep;
            (which == 0 ? dhdA : dhdB)[j] = (up - down) / (2.0 * step);
        }
    }
    const double scale = std::sqrt(std::max(1.0, fit.chi2PerDof));
    double varH = 0.0;
    for (std::size_t j = 0; j < n; ++j)
        varH += dhdA[j] * dhdA[j] * r.aErr[j] * r.aErr[j] + dhdB[j] * dhdB[j] * r.bErr[j] * r.bErr[j];
    fit.halfWidthErr = scale * std::sqrt(varH);
    for (std::size_t i = 0; i < n; ++i) {
        double var = 0.0;
        for (std::size_t j = 0; j < n; ++j) {
            const double dA = (i == j ? 1.0 : 0.0) - dhdA[j];
            var += dA * dA * r.aErr[j] * r.aErr[j] + dhdB[j] * dhdB[j] * r.bErr[j] * r.bErr[j];
        }
        fit.slipLength.push_back(r.a[i] - fit.halfWidth);
        fit.slipLengthErr.push_back(scale * std::sqrt(var));
    }
    return fit;
}

}  // namespace dpd
