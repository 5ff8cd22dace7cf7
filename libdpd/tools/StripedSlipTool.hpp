#pragma once
// stripedSlip: the continuum reference for striped walls (analysis/StripedSlip.hpp) from the command
// line, for scripts and tutorials: b_par, b_perp, their Belyaev-Vinogradova and Philip values, and, at
// the angles asked for, b_eff(theta) and a channel's transverse/longitudinal flux ratio. Printed as a
// dictionary (the format fit.dat uses).
#include "analysis/StripedSlip.hpp"

#include <iosfwd>
#include <vector>

namespace dpd {

struct StripedSlipQuery {
    StripedWall wall;
    std::vector<double> anglesDegrees;
};

void printStripedSlip(const StripedSlipQuery& q, std::ostream& out);

}  // namespace dpd
