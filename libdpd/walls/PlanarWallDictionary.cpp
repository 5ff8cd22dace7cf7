// A planar wall read from its sub-dictionary of constant/dpdProperties' walls block.
#include "walls/PlanarWallDictionary.hpp"

#include "io/Dictionary.hpp"
#include "walls/PlaneShape.hpp"
#include "walls/TunableSlipDictionary.hpp"
#include "walls/TunableSlipLayer.hpp"
#include "walls/WallRuleTypes.hpp"
#include "walls/WallTypes.hpp"

#include <cmath>
#include <optional>
#include <stdexcept>
#include <vector>

namespace dpd {

namespace {

// stripes { axis x; period 10; gasFraction 0.5; gammaGas 0.1; offset 0; } (docs/walls.md 3.6): the
// axis lies in the wall's plane.
TunableSlipStripes readStripes(const Dictionary& sd, const PlanarWallSettings& w, int dimension) {
    sd.checkKeys({"axis", "period", "gasFraction", "gammaGas", "offset"});
    TunableSlipStripes s;
    s.axis = sd.getAxis("axis");
    if (dimension == 2 && s.axis == 1) sd.fail("axis", "a 2-D scene has no y axis");
    if (std::abs(w.normal[s.axis]) > 1e-12) sd.fail("axis", "must lie in the wall's plane (across the stripes)");
    s.period = sd.getPositive<double>("period");
    s.gasFraction = sd.get<double>("gasFraction");
    if (!(s.gasFraction >= 0.0 && s.gasFraction <= 1.0)) sd.fail("gasFraction", "must lie in [0, 1]");
    s.gammaGas = sd.getNonNegative<double>("gammaGas");
    s.offset = sd.getOrDefault<double>("offset", 0.0);
    return s;
}

// slipLength b; (docs/walls.md 3.8): gammaL and the plane's offset behind `point` from the calibration
// of the case's fluid and of the wall's model (its tunableSlip block).
void resolvePlanarSlipLength(const Dictionary& wd, const WallReadContext& c, PlanarWallSettings& w) {
    requireSlipModel(wd);
    if (w.hasStripes) wd.subDict("tunableSlip").fail("stripes", "a wall that asks for a slipLength is uniform");
    const CalibratedWall chosen = resolveSlipLength(wd, c, w.tunableSlip, w.slipLength);
    w.tunableSlip.gammaL = chosen.gammaL;
    w.planeOffset = chosen.planeOffset;
}

PlanarWallSettings readPlanarWallSettings(const Dictionary& wd, const WallReadContext& c) {
    std::vector<std::string> keys{"type", "point", "normal", "velocity", "tunableSlip", "slipLength"};
    for (const std::string& k : wallRuleKeys()) keys.push_back(k);
    wd.checkKeys(keys);
    PlanarWallSettings w;
    w.name = c.name;
    w.point = wd.get<Eigen::Vector3d>("point");
    w.normal = wd.get<Eigen::Vector3d>("normal");
    if (w.normal.norm() == 0.0) wd.fail("normal", "must not be zero");
    w.normal.normalize();
    if (c.dimension == 2 && w.normal.y() != 0.0) wd.fail("normal", "a 2-D scene lies in the x-z plane: the y component must be 0");
    w.velocity = wd.getOrDefault<Eigen::Vector3d>("velocity", Eigen::Vector3d::Zero());
    if (std::abs(w.velocity.dot(w.normal)) > 1e-12) wd.fail("velocity", "a wall can only slide in its own plane");
    if (c.dimension == 2 && w.velocity.y() != 0.0) wd.fail("velocity", "a 2-D scene lies in the x-z plane: the y component must be 0");
    w.asksSlipLength = wd.found("slipLength");
    if (w.asksSlipLength) w.slipLength = wd.getNonNegative<double>("slipLength");
    if (wd.found("tunableSlip")) {
        if (!wd.isDict("tunableSlip")) wd.fail("tunableSlip", "expected { gammaL ...; zc ...; epsilon ...; sigma ...; }");
        w.hasTunableSlip = true;
        w.tunableSlip = readTunableSlip(wd.subDict("tunableSlip"), c.cutoff, w.asksSlipLength);
        if (c.dimension == 2 && w.tunableSlip.behindDensity > 0.0)
            wd.subDict("tunableSlip").fail("fluidBehind", "is the force of a 3-D half-space of fluid; a 2-D scene has none");
        if (wd.subDict("tunableSlip").found("stripes")) {
            w.hasStripes = true;
            w.stripes = readStripes(wd.subDict("tunableSlip").subDict("stripes"), w, c.dimension);
        }
    }
    if (w.asksSlipLength) resolvePlanarSlipLength(wd, c, w);
    // Behind a tunable-slip wall's WCA repulsion the rule is only a safety net: specular by default,
    // since it adds no tangential friction of its own to the slip that gammaL sets.
    const std::string defaultRule = w.hasTunableSlip ? "specular" : "bounceBack";
    w.rule = readWallRule(wd, defaultRule, c.cutoff);
    return w;
}

}  // namespace

std::unique_ptr<Wall> makePlanarWall(const PlanarWallSettings& settings, std::size_t index) {
    auto wall = std::make_unique<Wall>(settings.name, std::make_shared<PlaneShape>(settings.actingPoint(), settings.normal),
                                       settings.rule);
    wall->sliding(settings.velocity);
    if (settings.asksSlipLength) wall->askingSlipLength(settings.slipLength);
    if (settings.hasTunableSlip) {
        std::optional<TunableSlipStripes> stripes;
        if (settings.hasStripes) stripes = settings.stripes;
        wall->withForce(std::make_shared<TunableSlipLayer>(settings.tunableSlip, stripes, index));
    }
    return wall;
}

std::unique_ptr<Wall> readPlanarWall(const Dictionary& dict, const WallReadContext& context) {
    PlanarWallSettings settings = readPlanarWallSettings(dict, context);
    if (context.planes) context.planes->push_back(settings);
    return makePlanarWall(settings, context.index);
}

}  // namespace dpd
