#include "walls/StripedTunableSlipWall.hpp"

#include "core/Axis.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace dpd {

StripedTunableSlipWall::StripedTunableSlipWall(PlanarWallSettings settings, std::size_t index)
    : TunableSlipWall(std::move(settings), index) {
    if (!this->settings().hasStripes) throw std::invalid_argument("a striped wall needs its stripes");
}

std::string StripedTunableSlipWall::description() const {
    const TunableSlipStripes& s = settings().stripes;
    std::ostringstream os;
    os << TunableSlipWall::description() << ", stripes across " << axisLetter(s.axis) << " (period " << s.period
       << ", gas fraction " << s.gasFraction << " at gammaL " << s.gammaGas << ", offset " << s.offset << ")";
    return os.str();
}

std::string StripedTunableSlipWall::unfitFor(const Box& box) const {
    const TunableSlipStripes& s = settings().stripes;
    const double periods = box.length()[s.axis] / s.period;
    if (std::abs(periods - std::round(periods)) > 1e-9 * periods) {
        std::ostringstream os;
        os << "the box is " << box.length()[s.axis] << " long along " << axisLetter(s.axis) << ", not a whole number of stripe periods "
           << s.period << " (the stripes would not meet across the periodic boundary)";
        return os.str();
    }
    return {};
}

void StripedTunableSlipWall::markFlowAxes(const Box& box, std::array<bool, 3>& varies) const {
    TunableSlipWall::markFlowAxes(box, varies);
    varies[settings().stripes.axis] = true;
}

double StripedTunableSlipWall::frictionAt(double x, double y, double z) const {
    const TunableSlipStripes& s = settings().stripes;
    const double along = s.axis == 0 ? x : (s.axis == 1 ? y : z);
    return s.isGas(along) ? s.gammaGas : settings().tunableSlip.gammaL;
}

}  // namespace dpd
