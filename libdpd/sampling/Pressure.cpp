#include "sampling/Pressure.hpp"

#include "system/System.hpp"
#include "sampling/PairVirial.hpp"

namespace dpd {

double instantaneousPressure(const System& sys) {
    const Particles& p = sys.particles;
    const int d = sys.box.dimension;
    double twiceKinetic = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (sys.isFrozen(i)) continue;
        twiceKinetic += p.vx[i] * p.vx[i] + p.vz[i] * p.vz[i] + (d == 3 ? p.vy[i] * p.vy[i] : 0.0);
    }
    // One bin over the whole box along x: the Irving-Kirkwood shares of each pair sum to one.
    BinLayout whole;
    whole.axis = 0;
    whole.nBins = 1;
    whole.lo = sys.box.lo.x();
    whole.hi = sys.box.hi.x();
    const SymmetricTensor w = binnedPairVirial(sys, whole).front();
    const double virial = w[0] + w[2] + (d == 3 ? w[1] : 0.0);
    return (twiceKinetic + virial) / (d * sys.box.volume());
}

}  // namespace dpd
