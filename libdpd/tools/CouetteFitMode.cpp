#include "tools/CouetteFitMode.hpp"

#include "sampling/BinProfile.hpp"
#include "tools/FitModeParts.hpp"
#include "tools/FitSlipLengthTool.hpp"

#include <limits>
#include <tuple>

namespace dpd {

namespace {

// The component along which the walls slide: the one axis with a nonzero wall velocity component,
// -1 when there is not exactly one.
int wallSlidingAxis(const DpdModel& m) {
    int axis = -1, count = 0;
    for (int a = 0; a < 3; ++a) {
        bool moving = false;
        for (const PlanarWallSettings* w : m.planes()) moving = moving || w->velocity[a] != 0.0;
        if (moving) { axis = a; ++count; }
    }
    return count == 1 ? axis : -1;
}

// The component fitted: as given, or the one axis the walls slide along.
int couetteComponent(const FitSlipLengthSetup& s) {
    const Dictionary& d = s.dict;
    if (d.found("component")) return d.getAxis("component");
    const int a = wallSlidingAxis(s.model);
    if (a < 0)
        d.fail("component", "not given, and the walls of " + s.dpdProperties.fileName() +
                                " do not slide along exactly one axis: say which velocity component to fit");
    return a;
}

}  // namespace

std::string CouetteFitMode::name() const { return "couette"; }

void CouetteFitMode::read(FitSlipLengthSetup& s) const {
    const Dictionary& d = s.dict;
    if (s.model.bodyForce->active())
        s.dpdProperties.fail("bodyForce", "mode couette (" + d.fileName() + ") fits a line: it needs no body force");
    s.component = couetteComponent(s);
    if (d.found("fitRange")) {
        if (d.found("exclude")) d.fail("fitRange", "give either fitRange or exclude, not both");
        s.hasFitRange = true;
        std::tie(s.fitLow, s.fitHigh) = d.getIncreasingPair("fitRange", "low", "high");
    }
    s.exclude = d.found("exclude") ? d.getNonNegative<double>("exclude") : s.model.cutoff;
}

void CouetteFitMode::fit(const FitSlipLengthSetup& s, const ProfileTableData& t, const FitPoints& points,
                         FitSlipLengthResult& r) const {
    const ChannelBounds walls = channelBounds(s, t, r.axis);
    const double fitLow = s.hasFitRange ? s.fitLow : walls.low + s.exclude;
    const double fitHigh = s.hasFitRange ? s.fitHigh : walls.high - s.exclude;
    try {
        r.couette = fitCouette(points.profile, walls.low, walls.high, fitLow, fitHigh, walls.velocityLow, walls.velocityHigh);
        r.blockErrors = r.couette.blockErrors;
        r.stressColumn = shearStressName(s.component, r.axis);
        r.hasStress = t.has(r.stressColumn) && t.has(r.stressColumn + "Err");
        if (r.hasStress)
            r.stress = viscosityFromStress(t.column(t.axisName()), t.column(r.stressColumn), t.column(r.stressColumn + "Err"),
                                           r.couette, centralDensity(t), points.stressBlocks);
    } catch (const std::invalid_argument& e) {
        fitFailed(s, t, e);
    }
}

double CouetteFitMode::measuredNu(const FitSlipLengthResult& r) const {
    return r.hasStress ? r.stress.nu : std::numeric_limits<double>::quiet_NaN();
}

void CouetteFitMode::write(Dictionary& d, const FitSlipLengthResult& r) const {
    const CouetteFitResult& c = r.couette;
    if (r.hasStress) {
        d.setValue("nu", r.stress.nu);
        d.setValue("nuError", r.stress.nuErr);
        d.setValue("eta", r.stress.eta);
        d.setValue("etaError", r.stress.etaErr);
        d.setValue("shearStress", r.stress.stress);
        d.setValue("shearStressError", r.stress.stressErr);
    } else {
        d.setValue("nu", "none");  // no stress column in the profile table
    }
    d.setValue("fitRange", std::vector<double>{c.fitLow, c.fitHigh});
    setWallFits(d, c.lower, c.upper);
    d.setValue("shearRate", c.shearRate);
    d.setValue("shearRateError", c.shearRateErr);
    d.setValue("coefficients", c.coefficients);
    d.setValue("chi2PerDof", c.chi2PerDof);
    d.setValue("dof", c.dof);
}

void CouetteFitMode::print(const FitPrinter& out, const std::string& ax, const FitSlipLengthResult& r) const {
    const CouetteFitResult& c = r.couette;
    const auto num = &FitPrinter::num;
    const auto withErr = &FitPrinter::withErr;
    out.row("fit range", "[" + num(c.fitLow) + ", " + num(c.fitHigh) + "]");
    out.row("shear rate", withErr(c.shearRate, c.shearRateErr));
    if (r.hasStress) {
        out.row("shear stress", withErr(r.stress.stress, r.stress.stressErr), "(" + r.stressColumn + ")");
        out.row("eta", withErr(r.stress.eta, r.stress.etaErr));
        out.row("nu", withErr(r.stress.nu, r.stress.nuErr));
    } else {
        out.row("nu", "none (no column " + r.stressColumn + " in the profile: sample with stress yes)");
    }
    out.row("chi2/dof", num(c.chi2PerDof) + " (dof " + std::to_string(c.dof) + ")");
    out.row("", "lower wall (" + ax + " = " + num(c.lower.position) + ")",
            "upper wall (" + ax + " = " + num(c.upper.position) + ")");
    out.row("wall velocity", num(c.lower.wallVelocity), num(c.upper.wallVelocity));
    out.row("slip length", withErr(c.lower.slipLength, c.lower.slipLengthErr),
            withErr(c.upper.slipLength, c.upper.slipLengthErr));
    out.row("slip velocity", withErr(c.lower.slipVelocity, c.lower.slipVelocityErr),
            withErr(c.upper.slipVelocity, c.upper.slipVelocityErr));
}

}  // namespace dpd
