#include "walls/GeometryWallDictionary.hpp"

#include "io/Dictionary.hpp"
#include "walls/GeometryShape.hpp"
#include "walls/TunableSlipDictionary.hpp"
#include "walls/TunableSlipLayer.hpp"
#include "walls/WallRuleTypes.hpp"
#include "walls/WallTypes.hpp"

#include <optional>
#include <vector>

namespace dpd {

namespace {

// The tunable-slip layer along the geometry's surface (docs/walls.md 3.9), its friction given or, for
// `slipLength b;`, from the case's calibration with the acting surface moved behind the geometry's.
// Returns the surface offset.
double readGeometrySlip(const Dictionary& d, const WallReadContext& c, TunableSlipParameters& model,
                        std::optional<double> askedSlipLength) {
    const bool asksSlipLength = askedSlipLength.has_value();
    if (!d.isDict("tunableSlip")) d.fail("tunableSlip", "expected { gammaL ...; zc ...; epsilon ...; sigma ...; }");
    const Dictionary& td = d.subDict("tunableSlip");
    if (td.found("stripes")) td.fail("stripes", "stripes run along an axis of a plane: a planar wall's (type plane)");
    model = readTunableSlip(td, c.cutoff, asksSlipLength);
    if (c.dimension == 2 && model.behindDensity > 0.0)
        td.fail("fluidBehind", "is the force of a 3-D half-space of fluid; a 2-D scene has none");
    if (!asksSlipLength) return 0.0;
    const CalibratedWall chosen = resolveSlipLength(d, c, model, *askedSlipLength);
    // The field reaches two cutoffs into the solid; the friction layer needs one of it behind the surface.
    if (chosen.planeOffset > c.cutoff)
        d.fail("slipLength", "puts the acting surface " + std::to_string(chosen.planeOffset) +
                                 " behind the geometry's, more than the cutoff a geometry wall allows");
    model.gammaL = chosen.gammaL;
    return chosen.planeOffset;
}

}  // namespace

std::unique_ptr<Wall> readGeometryWall(const Dictionary& d, const WallReadContext& c) {
    std::vector<std::string> keys{"type", "tunableSlip", "slipLength"};
    for (const std::string& k : wallRuleKeys()) keys.push_back(k);
    d.checkKeys(keys);
    if (!c.geometry) d.fail("type", "a geometry wall needs the geometry block it acts on (constant/dpdProperties' geometry)");
    requireSlipModel(d);
    if (!d.found("tunableSlip"))
        return std::make_unique<Wall>(c.name, std::make_shared<GeometryShape>(c.geometry), readWallRule(d, "bounceBack", c.cutoff));
    const std::optional<double> askedSlipLength =
        d.found("slipLength") ? std::optional<double>(d.getNonNegative<double>("slipLength")) : std::nullopt;
    TunableSlipParameters model;
    const double offset = readGeometrySlip(d, c, model, askedSlipLength);
    // Behind the WCA repulsion the rule is a safety net, specular by default (as a planar tunable-slip wall).
    auto wall = std::make_unique<Wall>(c.name, std::make_shared<GeometryShape>(c.geometry, offset),
                                       readWallRule(d, "specular", c.cutoff));
    wall->withForce(std::make_shared<TunableSlipLayer>(model, std::nullopt, c.index));
    if (askedSlipLength) wall->askingSlipLength(*askedSlipLength);
    return wall;
}

}  // namespace dpd
