#include "setup/StandardFluid.hpp"

#include "setup/InitialConditions.hpp"

#include <cmath>

namespace dpd {

System makeStandardFluid(const StandardFluidSettings& s) {
    System sys;
    const double volume = s.particles / s.density;
    const Eigen::Vector3d a = s.aspect;
    const double unit = s.dimension == 3 ? std::cbrt(volume / (a.x() * a.y() * a.z())) : std::sqrt(volume / (a.x() * a.z()));
    sys.box.dimension = s.dimension;
    sys.box.lo = Eigen::Vector3d(0, 0, 0);
    sys.box.hi = Eigen::Vector3d(unit * a.x(), s.dimension == 3 ? unit * a.y() : 1.0, unit * a.z());
    sys.species.add({"fluid", false});
    sys.pairs = PairTable(1);
    sys.pairs.set(0, 0, {s.a, s.gamma, 0.0, true});
    sys.forceParameters = {s.cutoff, 2.0, s.kT, s.dt};
    sys.seed = s.seed;
    const PairRandom random(s.seed);
    fillRandom(sys.particles, sys.box, sys.box.lo, sys.box.hi, s.density, 0,
               [](double, double, double) { return true; }, random, 0);
    maxwellVelocities(sys.particles, 0, sys.particles.size(), s.dimension, s.kT, random);
    sys.ranks = s.ranks;
    sys.initialise();
    sys.sortByCell();
    sys.computeForces();
    sys.dropGhosts();
    return sys;
}

}  // namespace dpd
