#include "tools/FitModeParts.hpp"

#include "core/Axis.hpp"
#include "core/Error.hpp"
#include "tools/FitMode.hpp"
#include "tools/FitSlipLengthTool.hpp"

#include <limits>
#include <ostream>
#include <sstream>

namespace dpd {

namespace {

std::string vectorText(const Eigen::Vector3d& v) {
    std::ostringstream os;
    os << "(" << v.x() << " " << v.y() << " " << v.z() << ")";
    return os.str();
}

}  // namespace

std::pair<const PlanarWallSettings*, const PlanarWallSettings*> channelWalls(const FitSlipLengthSetup& s, const ProfileTableData& t,
                                                              int axis) {
    std::vector<const PlanarWallSettings*> walls;
    for (const PlanarWallSettings* w : s.model.planes())
        if (w->normalAxis() == axis) walls.push_back(w);
    if (walls.size() != 2)
        s.dpdProperties.fail("walls", "mode " + s.mode->name() + " needs exactly two planar walls with normals along " +
                                          t.axisName() + " (the axis of " + t.file + "), found " +
                                          std::to_string(walls.size()));
    if (walls[0]->point[axis] > walls[1]->point[axis]) std::swap(walls[0], walls[1]);
    const PlanarWallSettings& lower = *walls[0];
    const PlanarWallSettings& upper = *walls[1];
    if (!(lower.normal[axis] > 0.0 && upper.normal[axis] < 0.0 && upper.point[axis] > lower.point[axis]))
        s.dpdProperties.fail("walls", "walls '" + lower.name + "' and '" + upper.name +
                                          "' do not face each other across a channel along " + t.axisName());
    return {walls[0], walls[1]};
}

ChannelBounds channelBounds(const FitSlipLengthSetup& s, const ProfileTableData& t, int axis) {
    if (!s.hasWallPositions) {
        const auto [lower, upper] = channelWalls(s, t, axis);
        return {lower->point[axis], upper->point[axis], lower->velocity[s.component], upper->velocity[s.component]};
    }
    for (const PlanarWallSettings* w : s.model.planes())
        if (w->normalAxis() == axis)
            s.dict.fail("wallPositions", "the case has planar walls with normals along " + t.axisName() + " ('" +
                                             w->name + "' in " + s.dpdProperties.fileName() +
                                             "): their positions are used; wallPositions is for the walls of a "
                                             "geometry block");
    return {s.wallLow, s.wallHigh, 0.0, 0.0};
}

int bodyForceComponent(const FitSlipLengthSetup& s) {
    const Dictionary& d = s.dict;
    const Eigen::Vector3d g = s.model.bodyForce->value();
    const std::string dpdFile = s.dpdProperties.fileName();
    int component = -1;
    if (d.found("component")) {
        component = d.getAxis("component");
    } else {
        int nonzero = 0;
        for (int a = 0; a < 3; ++a)
            if (g[a] != 0.0) {
                component = a;
                ++nonzero;
            }
        if (nonzero != 1)
            d.fail("component", "not given, and the body force " + vectorText(g) + " of " + dpdFile +
                                    " does not point along one axis: say which velocity component to fit");
    }
    if (g[component] == 0.0)
        d.fail("component", std::string("the body force ") + vectorText(g) + " of " + dpdFile + " has no " +
                                axisLetter(component) + " component: nothing drives a flow along " + axisLetter(component));
    return component;
}

void binRange(const ProfileTableData& t, double& lo, double& hi) {
    const std::vector<double>& c = t.column(t.axisName());
    if (c.size() < 2) throw IoError(t.file + ": a profile needs at least 2 bins to tell its range");
    const double w = (c.back() - c.front()) / static_cast<double>(c.size() - 1);
    if (!(w > 0.0)) throw IoError(t.file + ": the bin centres of column '" + t.axisName() + "' do not increase");
    lo = c.front() - 0.5 * w;
    hi = c.back() + 0.5 * w;
}

double centralDensity(const ProfileTableData& t) {
    double lo, hi;
    binRange(t, lo, hi);
    const double a = lo + 0.25 * (hi - lo), b = hi - 0.25 * (hi - lo);
    const std::vector<double>& y = t.column(t.axisName());
    const std::vector<double>& rho = t.column("density");
    const std::vector<double>* count = t.has("count") ? &t.column("count") : nullptr;
    double sum = 0.0, weight = 0.0;
    for (std::size_t i = 0; i < y.size(); ++i) {
        if (y[i] < a || y[i] > b) continue;
        const double w = count ? (*count)[i] : 1.0;
        sum += w * rho[i];
        weight += w;
    }
    return weight > 0.0 ? sum / weight : std::numeric_limits<double>::quiet_NaN();
}

void fitFailed(const FitSlipLengthSetup& s, const ProfileTableData& t, const std::invalid_argument& e) {
    const Dictionary& d = s.dict;
    const std::string key = d.found("fitRange") ? "fitRange" : d.found("exclude") ? "exclude" : "";
    throw InputError(d.fileName(), key.empty() ? 0 : d.lineOf(key), key,
                     "cannot fit the profile " + t.file + ": " + e.what());
}

void setWallFits(Dictionary& d, const WallFitResult& lower, const WallFitResult& upper) {
    d.setValue("wallPosition", std::vector<double>{lower.position, upper.position});
    d.setValue("wallVelocity", std::vector<double>{lower.wallVelocity, upper.wallVelocity});
    d.setValue("slipLength", std::vector<double>{lower.slipLength, upper.slipLength});
    d.setValue("slipLengthError", std::vector<double>{lower.slipLengthErr, upper.slipLengthErr});
    d.setValue("slipVelocity", std::vector<double>{lower.slipVelocity, upper.slipVelocity});
    d.setValue("slipVelocityError", std::vector<double>{lower.slipVelocityErr, upper.slipVelocityErr});
}

}  // namespace dpd
