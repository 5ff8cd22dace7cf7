#include "tools/StripedSlipTool.hpp"

#include <cmath>
#include <iomanip>
#include <ostream>

namespace dpd {

void printStripedSlip(const StripedSlipQuery& q, std::ostream& out) {
    const StripedWall& w = q.wall;
    const SlipTensor slip = stripedSlipTensor(w);
    const bool channel = std::isfinite(w.height);
    out << std::setprecision(8) << "period          " << w.period << ";\n"
        << "gasFraction     " << w.slipFraction << ";\n"
        << "localSlip       " << w.localSlip << ";\n"
        << "height          " << w.height << ";\n"
        << "stripedWalls    " << w.stripedWalls << ";\n"
        << "slipParallel    " << slip.parallel << ";\n"
        << "slipPerpendicular " << slip.perpendicular << ";\n";
    if (!channel) {
        out << "belyaevVinogradovaParallel " << belyaevVinogradovaLongitudinalSlip(w.period, w.slipFraction, w.localSlip) << ";\n"
            << "belyaevVinogradovaPerpendicular " << belyaevVinogradovaTransverseSlip(w.period, w.slipFraction, w.localSlip) << ";\n"
            << "philipParallel  " << philipLongitudinalSlip(w.period, w.slipFraction) << ";\n"
            << "philipPerpendicular " << philipTransverseSlip(w.period, w.slipFraction) << ";\n";
    }
    for (double degrees : q.anglesDegrees) {
        const double theta = degrees * M_PI / 180.0;
        out << "angle" << degrees << " { slip " << effectiveSlip(slip, theta) << ";";
        if (channel) out << " transverseFluxRatio " << transverseFluxRatio(slip, w.height, w.stripedWalls, theta) << ";";
        out << " }\n";
    }
}

}  // namespace dpd
