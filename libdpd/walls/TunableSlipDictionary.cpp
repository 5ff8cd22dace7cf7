#include "walls/TunableSlipDictionary.hpp"

#include "core/Error.hpp"
#include "io/Dictionary.hpp"
#include "walls/WallTypes.hpp"

#include <exception>

namespace dpd {

TunableSlipParameters readTunableSlip(const Dictionary& td, double cutoff, bool asksSlipLength) {
    td.checkKeys({"gammaL", "zc", "epsilon", "sigma", "stripes", "friction", "fluidBehind"});
    TunableSlipParameters t;
    if (asksSlipLength && td.found("gammaL"))
        td.fail("gammaL", "the wall asks for a slipLength, which sets gammaL from the slip calibration: give one of the two");
    if (!asksSlipLength) t.gammaL = td.getNonNegative<double>("gammaL");
    t.zc = td.getPositive<double>("zc");
    t.epsilon = td.getPositive<double>("epsilon");
    t.sigma = td.getPositive<double>("sigma");
    const std::string friction = td.getOrDefault<std::string>("friction", "all");
    if (friction != "all" && friction != "tangential")
        td.fail("friction", "expected all (every velocity component) or tangential (along the plane), got '" + friction + "'");
    t.tangentialOnly = friction == "tangential";
    t.cutoff = cutoff;
    if (td.found("fluidBehind")) {
        if (!td.isDict("fluidBehind")) td.fail("fluidBehind", "expected { a ...; density ...; }");
        const Dictionary& bd = td.subDict("fluidBehind");
        bd.checkKeys({"a", "density"});
        t.behindA = bd.getPositive<double>("a");
        t.behindDensity = bd.getNonNegative<double>("density");  // 0: no fluid behind, the published wall
    }
    return t;
}

void requireSlipModel(const Dictionary& wd) {
    if (wd.found("slipLength") && !wd.found("tunableSlip"))
        wd.fail("slipLength", "needs the wall's model: tunableSlip { zc ...; epsilon ...; sigma ...; } (gammaL comes from "
                              "the slip calibration)");
}

CalibratedWall resolveSlipLength(const Dictionary& wd, const WallReadContext& c, const TunableSlipParameters& model,
                                 double b) {
    if (!c.slipLengths) wd.fail("slipLength", "is resolved against the case's slip calibration: read it with its case");
    try {
        CalibratedWall chosen = c.slipLengths->resolve(model, b);
        if (c.notes) c.notes->push_back("wall " + c.name + ": " + chosen.note);
        return chosen;
    } catch (const InputError&) {
        throw;  // another file's entry (the controlDict's deltaT, the builder's density) names itself
    } catch (const std::exception& e) {
        wd.fail("slipLength", e.what());
    }
    return {};
}

}  // namespace dpd
