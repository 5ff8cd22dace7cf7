#pragma once
// What the fit modes of fitSlipLength share: the channel's walls, the component driven by the body
// force, the bins' range, the central density, and the per-wall entries of fit.dat.
#include "analysis/PoiseuilleFit.hpp"
#include "io/Dictionary.hpp"
#include "sampling/ProfileTable.hpp"
#include "walls/PlanarWallSettings.hpp"

#include <stdexcept>
#include <utility>

namespace dpd {

struct FitSlipLengthSetup;

// The two planar walls facing each other across the profile's axis, lower first.
std::pair<const PlanarWallSettings*, const PlanarWallSettings*> channelWalls(const FitSlipLengthSetup& s, const ProfileTableData& t,
                                                              int axis);

// The channel's two walls along the profile's axis, as the fits need them: the planar walls of
// dpdProperties, or the positions wallPositions gives (the solid of a geometry block, at rest).
struct ChannelBounds {
    double low = 0.0, high = 0.0;                  // wall positions along the axis
    double velocityLow = 0.0, velocityHigh = 0.0;  // the walls' velocities along the fitted component
};
ChannelBounds channelBounds(const FitSlipLengthSetup& s, const ProfileTableData& t, int axis);

// The component fitted in a body-force-driven mode: as given, or the one axis the force points along.
int bodyForceComponent(const FitSlipLengthSetup& s);

// The bins' range: first centre - half a bin to last centre + half a bin.
void binRange(const ProfileTableData& t, double& lo, double& hi);
// Count-weighted mean density of the bins in the central half of the bin range.
double centralDensity(const ProfileTableData& t);

// An InputError at the dictionary's fitRange or exclude (the keys that set what is fitted).
[[noreturn]] void fitFailed(const FitSlipLengthSetup& s, const ProfileTableData& t, const std::invalid_argument& e);

// The per-wall entries fit.dat has in both channel modes: (lower upper) lists.
void setWallFits(Dictionary& d, const WallFitResult& lower, const WallFitResult& upper);

}  // namespace dpd
