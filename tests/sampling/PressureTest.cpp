// The instantaneous pressure of sampling/Pressure.hpp against hand-computed values: a single pair
// at rest gives P = a (1 - r) r / (3 V) (r . F_C = a (1 - r / rc) r with rc = 1); moving the pair
// perpendicular to its separation adds only the kinetic part sum v^2 / (3 V) (the dissipative force
// acts along r and vanishes, r . v_ij = 0); a pair straddling the periodic boundary counts once whole.
#include "sampling/Pressure.hpp"
#include "system/System.hpp"

#include <gtest/gtest.h>

using namespace dpd;

namespace {

// A 5 x 5 x 5 periodic box (five cells per axis) holding two particles of one species.
System pairSystem(double x1, double x2, double vy1, double vy2) {
    System sys;
    sys.box.lo = Eigen::Vector3d(0, 0, 0);
    sys.box.hi = Eigen::Vector3d(5, 5, 5);
    sys.species.add({"fluid", false});
    sys.pairs = PairTable(1);
    sys.pairs.set(0, 0, {25.0, 4.5, 0.0, true});
    sys.forceParameters = {1.0, 2.0, 1.0, 0.01};
    sys.particles.add(0, 0, x1, 2.5, 2.5, 0.0, vy1, 0.0);
    sys.particles.add(1, 0, x2, 2.5, 2.5, 0.0, vy2, 0.0);
    sys.initialise();
    sys.sortByCell();
    return sys;
}

constexpr double kVolume = 125.0;

}  // namespace

TEST(Pressure, PairAtRestGivesItsConservativeVirial) {
    const double r = 0.4;
    const System sys = pairSystem(2.0, 2.0 + r, 0.0, 0.0);
    EXPECT_NEAR(instantaneousPressure(sys), 25.0 * (1.0 - r) * r / (3.0 * kVolume), 1e-12);
}

TEST(Pressure, MovingPairAddsItsKineticPartOnly) {
    const double r = 0.7;
    const System sys = pairSystem(1.0, 1.0 + r, 1.5, -0.5);
    const double expected = (1.5 * 1.5 + 0.5 * 0.5 + 25.0 * (1.0 - r) * r) / (3.0 * kVolume);
    EXPECT_NEAR(instantaneousPressure(sys), expected, 1e-12);
}

TEST(Pressure, PairAcrossThePeriodicBoundaryCountsOnceWhole) {
    const double r = 0.6;  // particles at x 4.8 and 0.4: separation 0.6 through x = 5
    const System sys = pairSystem(4.8, 0.4, 0.0, 0.0);
    EXPECT_NEAR(instantaneousPressure(sys), 25.0 * (1.0 - r) * r / (3.0 * kVolume), 1e-12);
}
