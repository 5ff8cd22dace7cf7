#include "tools/ReversePoiseuilleFitMode.hpp"

#include "core/Axis.hpp"
#include "forces/ReversePoiseuilleBodyForce.hpp"
#include "tools/FitModeParts.hpp"
#include "tools/FitSlipLengthTool.hpp"

namespace dpd {

std::string ReversePoiseuilleFitMode::name() const { return "reversePoiseuille"; }

void ReversePoiseuilleFitMode::read(FitSlipLengthSetup& s) const {
    const Dictionary& d = s.dict;
    const BodyForce& f = *s.model.bodyForce;
    if (d.found("fitRange")) d.fail("fitRange", "only mode couette takes a fitRange (use exclude)");
    if (!dynamic_cast<const ReversePoiseuilleBodyForce*>(&f) || !f.active())
        d.fail("mode", "mode reversePoiseuille needs a nonzero body force of type reversePoiseuille in " +
                           s.dpdProperties.fileName());
    if (s.hasWallPositions) d.fail("wallPositions", "mode reversePoiseuille has no walls");
    s.component = bodyForceComponent(s);
    s.exclude = d.found("exclude") ? d.getNonNegative<double>("exclude") : 1.0;
}

void ReversePoiseuilleFitMode::fit(const FitSlipLengthSetup& s, const ProfileTableData& t, const FitPoints& points,
                                   FitSlipLengthResult& r) const {
    const int gradientAxis = s.model.bodyForce->gradientAxis();
    if (r.axis != gradientAxis)
        s.dpdProperties.fail("bodyForce", "the reversePoiseuille gradientAxis is " + std::string(axisLetter(gradientAxis)) +
                                              " but the profile " + t.file + " is binned along " + t.axisName());
    double lo, hi;
    binRange(t, lo, hi);
    r.boxLow = lo;
    r.boxLength = hi - lo;
    try {
        r.reverse = fitReversePoiseuille(points.profile, r.g, r.boxLow, r.boxLength, s.exclude);
        r.blockErrors = r.reverse.blockErrors;
    } catch (const std::invalid_argument& e) {
        fitFailed(s, t, e);
    }
}

double ReversePoiseuilleFitMode::measuredNu(const FitSlipLengthResult& r) const { return r.reverse.nu; }

void ReversePoiseuilleFitMode::write(Dictionary& d, const FitSlipLengthResult& r) const {
    const ReversePoiseuilleResult& p = r.reverse;
    d.setValue("boxLow", r.boxLow);
    d.setValue("boxLength", r.boxLength);
    d.setValue("nu", p.nu);
    d.setValue("nuError", p.nuErr);
    d.setValue("nuFirstHalf", p.nuFirstHalf);
    d.setValue("nuFirstHalfError", p.nuFirstHalfErr);
    d.setValue("nuSecondHalf", p.nuSecondHalf);
    d.setValue("nuSecondHalfError", p.nuSecondHalfErr);
    d.setValue("chi2PerDof", p.chi2PerDof);
}

void ReversePoiseuilleFitMode::print(const FitPrinter& out, const std::string& ax, const FitSlipLengthResult& r) const {
    const ReversePoiseuilleResult& p = r.reverse;
    const auto num = &FitPrinter::num;
    const auto withErr = &FitPrinter::withErr;
    out.row("box along " + ax, "[" + num(r.boxLow) + ", " + num(r.boxLow + r.boxLength) + ")");
    out.row("nu", withErr(p.nu, p.nuErr));
    out.row("nu (+g half)", withErr(p.nuFirstHalf, p.nuFirstHalfErr));
    out.row("nu (-g half)", withErr(p.nuSecondHalf, p.nuSecondHalfErr));
    out.row("chi2/dof", num(p.chi2PerDof));
}

}  // namespace dpd
