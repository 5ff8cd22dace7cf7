#include "setup/InitialFlow.hpp"

#include "analysis/PoiseuilleFit.hpp"
#include "forces/ReversePoiseuilleBodyForce.hpp"
#include "io/Dictionary.hpp"
#include "case/DpdProperties.hpp"

#include <cmath>
#include <string>
#include <tuple>

namespace dpd {

Eigen::Vector3d InitialFlow::velocityAt(double s) const {
    if (type == Type::none || s <= lower || s >= upper) return Eigen::Vector3d::Zero();
    if (type == Type::poiseuille) return g * ((s - lower) * (upper - s) / (2.0 * nu));
    const double half = 0.5 * (upper - lower);
    const double t = s - lower;
    if (t < half) return g * (t * (half - t) / (2.0 * nu));
    return -g * ((t - half) * (2.0 * half - t) / (2.0 * nu));
}

namespace {

// The uniform body force a Poiseuille start between walls normal to `axis` needs.
void channelBodyForce(const Dictionary& d, const DpdModel& model, int axis, InitialFlow& flow) {
    const BodyForce& f = *model.bodyForce;
    if (!f.uniform() || !f.active()) d.fail("type", "a poiseuille start needs a uniform body force in constant/dpdProperties");
    if (f.value()[axis] != 0.0)
        d.fail("type", "the body force has a component along the walls' normal: no steady channel flow");
    flow.g = f.value();
}

// The channel of a Poiseuille start between the walls of a geometry block: axis and wallPositions.
void channelFromPositions(const Dictionary& d, const DpdModel& model, InitialFlow& flow) {
    if (!d.found("axis") || !d.found("wallPositions"))
        d.fail(d.found("axis") ? "axis" : "wallPositions", "give both axis and wallPositions (the walls of a geometry)");
    if (!model.planes().empty())
        d.fail("wallPositions", "constant/dpdProperties has planar walls: the start uses theirs; wallPositions is for "
                                "the walls of a geometry block");
    flow.axis = d.getAxis("axis");
    std::tie(flow.lower, flow.upper) = d.getIncreasingPair("wallPositions", "lower", "upper");
    channelBodyForce(d, model, flow.axis, flow);
}

// Fills the channel geometry of a Poiseuille start from the model's walls and body force.
void channelFromModel(const Dictionary& d, const DpdModel& model, InitialFlow& flow) {
    if (d.found("axis") || d.found("wallPositions")) {
        channelFromPositions(d, model, flow);
        return;
    }
    const std::vector<const PlanarWallSettings*> walls = model.planes();
    if (walls.size() != 2)
        d.fail("type", "a poiseuille start needs exactly two planar walls in constant/dpdProperties (or, for the "
                       "walls of a geometry, axis and wallPositions)");
    const int axis = walls[0]->normalAxis();
    if (axis < 0 || walls[1]->normalAxis() != axis || walls[0]->normal.dot(walls[1]->normal) > -0.5)
        d.fail("type", "a poiseuille start needs two parallel axis-aligned walls facing each other");
    for (const PlanarWallSettings* w : walls)
        if (w->velocity.squaredNorm() > 0.0)
            d.fail("type", "a poiseuille start needs walls at rest (wall '" + w->name + "' moves)");
    channelBodyForce(d, model, axis, flow);
    // The solid lies behind each wall: the wall whose normal points up the axis is the lower one.
    const bool firstIsLower = walls[0]->normal[axis] > 0.0;
    flow.axis = axis;
    flow.lower = (firstIsLower ? walls[0] : walls[1])->point[axis];
    flow.upper = (firstIsLower ? walls[1] : walls[0])->point[axis];
}

// The periodic box of a reverse-Poiseuille start.
void periodicBoxFromModel(const Dictionary& d, const DpdModel& model, const Box& box, InitialFlow& flow) {
    if (!model.planes().empty()) d.fail("type", "a reversePoiseuille start needs a box without walls");
    const BodyForce& f = *model.bodyForce;
    if (!dynamic_cast<const ReversePoiseuilleBodyForce*>(&f) || !f.active())
        d.fail("type", "a reversePoiseuille start needs a reversePoiseuille body force in constant/dpdProperties");
    flow.axis = f.gradientAxis();
    flow.lower = box.lo[flow.axis];
    flow.upper = box.hi[flow.axis];
    flow.g = f.value();
}

}  // namespace

InitialFlow readInitialFlow(const Dictionary& fluidDict, const DpdModel& model, const Box& box, int fluidSpecies,
                            double density) {
    InitialFlow flow;
    if (!fluidDict.found("initialFlow")) return flow;
    const Dictionary& d = fluidDict.subDict("initialFlow");
    d.checkKeys({"type", "nu", "axis", "wallPositions"});
    const std::string type = d.get<std::string>("type");
    if (type == "none") return flow;
    if (type == "poiseuille") {
        flow.type = InitialFlow::Type::poiseuille;
        channelFromModel(d, model, flow);
    } else if (type == "reversePoiseuille") {
        if (d.found("wallPositions")) d.fail("wallPositions", "a reversePoiseuille start has no walls");
        flow.type = InitialFlow::Type::reversePoiseuille;
        periodicBoxFromModel(d, model, box, flow);
    } else {
        d.fail("type", "unknown initial flow '" + type + "' (expected none, poiseuille or reversePoiseuille)");
    }
    flow.nu = d.found("nu") ? d.getPositive<double>("nu")
                            : kineticTheoryViscosity(model.kT, model.pairs(fluidSpecies, fluidSpecies).gamma,
                                                     density, model.cutoff);
    return flow;
}

void addInitialFlow(Particles& p, std::size_t begin, std::size_t end, const InitialFlow& flow) {
    if (flow.type == InitialFlow::Type::none) return;
    const ParticleArray<double>& coordinate = p.position(flow.axis);
    for (std::size_t i = begin; i < end; ++i) {
        const Eigen::Vector3d u = flow.velocityAt(coordinate[i]);
        p.vx[i] += u.x();
        p.vy[i] += u.y();
        p.vz[i] += u.z();
    }
}

}  // namespace dpd
