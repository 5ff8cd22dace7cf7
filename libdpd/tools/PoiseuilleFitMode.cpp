#include "tools/PoiseuilleFitMode.hpp"

#include "forces/ReversePoiseuilleBodyForce.hpp"

#include "tools/FitModeParts.hpp"
#include "tools/FitSlipLengthTool.hpp"

#include <cmath>

namespace dpd {

std::string PoiseuilleFitMode::name() const { return "poiseuille"; }

void PoiseuilleFitMode::read(FitSlipLengthSetup& s) const {
    const Dictionary& d = s.dict;
    const BodyForce& f = *s.model.bodyForce;
    if (d.found("fitRange")) d.fail("fitRange", "only mode couette takes a fitRange (use exclude)");
    if (dynamic_cast<const ReversePoiseuilleBodyForce*>(&f))
        d.fail("mode", s.dpdProperties.fileName() + " has a reversePoiseuille body force: use mode reversePoiseuille");
    if (!f.uniform() || !f.active())
        s.dpdProperties.fail("bodyForce", "mode poiseuille (" + d.fileName() + ") needs a uniform nonzero body force");
    s.component = bodyForceComponent(s);
    s.exclude = d.found("exclude") ? d.getNonNegative<double>("exclude") : 0.0;
}

void PoiseuilleFitMode::fit(const FitSlipLengthSetup& s, const ProfileTableData& t, const FitPoints& points,
                            FitSlipLengthResult& r) const {
    const ChannelBounds walls = channelBounds(s, t, r.axis);
    try {
        r.poiseuille = fitPoiseuille(points.profile, r.g, walls.low, walls.high, s.exclude, walls.velocityLow, walls.velocityHigh);
        r.blockErrors = r.poiseuille.blockErrors;
    } catch (const std::invalid_argument& e) {
        fitFailed(s, t, e);
    }
}

double PoiseuilleFitMode::measuredNu(const FitSlipLengthResult& r) const { return r.poiseuille.nu; }

std::vector<double> PoiseuilleFitMode::jackknifed(const FitSlipLengthResult& r) const {
    const PoiseuilleFitResult& p = r.poiseuille;
    return {p.nu, p.lower.slipLength, p.upper.slipLength, p.lower.slipVelocity, p.upper.slipVelocity};
}

void PoiseuilleFitMode::setJackknifeErrors(FitSlipLengthResult& r, const std::vector<double>& e) const {
    PoiseuilleFitResult& p = r.poiseuille;
    p.nuErr = e[0];
    p.lower.slipLengthErr = e[1];
    p.upper.slipLengthErr = e[2];
    p.lower.slipVelocityErr = e[3];
    p.upper.slipVelocityErr = e[4];
}

// The slowest transverse momentum mode between the walls: d^2 / (pi^2 nu) (docs/analysis.md 5.2).
double PoiseuilleFitMode::decayTime(const FitSlipLengthResult& r) const {
    const double d = r.poiseuille.upper.position - r.poiseuille.lower.position;
    return d * d / (M_PI * M_PI * r.poiseuille.nu);
}

void PoiseuilleFitMode::write(Dictionary& d, const FitSlipLengthResult& r) const {
    const PoiseuilleFitResult& p = r.poiseuille;
    d.setValue("nu", p.nu);
    d.setValue("nuError", p.nuErr);
    setWallFits(d, p.lower, p.upper);
    d.setValue("shearRate", std::vector<double>{p.lower.shearRate, p.upper.shearRate});
    d.setValue("centre", p.centre);
    d.setValue("maxVelocity", p.maxVelocity);
    d.setValue("coefficients", p.coefficients);
    d.setValue("chi2PerDof", p.chi2PerDof);
    d.setValue("dof", p.dof);
}

void PoiseuilleFitMode::print(const FitPrinter& out, const std::string& ax, const FitSlipLengthResult& r) const {
    const PoiseuilleFitResult& p = r.poiseuille;
    const auto num = &FitPrinter::num;
    const auto withErr = &FitPrinter::withErr;
    out.row("nu", withErr(p.nu, p.nuErr));
    out.row("chi2/dof", num(p.chi2PerDof) + " (dof " + std::to_string(p.dof) + ")");
    out.row("", "lower wall (" + ax + " = " + num(p.lower.position) + ")",
            "upper wall (" + ax + " = " + num(p.upper.position) + ")");
    out.row("slip length", withErr(p.lower.slipLength, p.lower.slipLengthErr),
            withErr(p.upper.slipLength, p.upper.slipLengthErr));
    out.row("slip velocity", withErr(p.lower.slipVelocity, p.lower.slipVelocityErr),
            withErr(p.upper.slipVelocity, p.upper.slipVelocityErr));
    out.row("shear rate", num(p.lower.shearRate), num(p.upper.shearRate));
}

}  // namespace dpd
