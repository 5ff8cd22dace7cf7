// The force list after the pair force is built from the registered terms (system/ForceTermTypes.cpp):
// a scene has the terms it needs (the body force's always: it may be set later), in the registry's order, and the velocity predictor's
// question (does a term read v?) is answered by the terms it has.
#include "../forces/ChainTestSystems.hpp"
#include "forces/UniformBodyForce.hpp"
#include "setup/StandardFluid.hpp"
#include "system/ForceTerm.hpp"
#include "system/System.hpp"

#include <gtest/gtest.h>

using namespace dpd;

namespace {

using Types = std::vector<std::string>;

StandardFluidSettings smallFluid() {
    StandardFluidSettings s;
    s.particles = 375;  // density 3 in a cube of side 5
    return s;
}

ChainedFluidSettings chainedFluid(BondedPairs::Mode mode) {
    ChainedFluidSettings c;
    c.fluid = smallFluid();
    c.chains = 3;
    c.length = 5;
    c.bondedPairs.mode = mode;
    return c;
}

}  // namespace

TEST(ForceTerms, TheRegistryListsTheTermsInTheOrderTheirForcesAreAdded) {
    EXPECT_EQ(forceTermRegistry().names(), (Types{"bondedPairCorrection", "bodyForce", "bonds", "wallForces"}));
}

TEST(ForceTerms, TheFluidAloneHasOnlyTheBodyForcesTermAfterThePairForce) {
    const System sys = makeStandardFluid(smallFluid());
    EXPECT_EQ(sys.forceTermTypes(), Types{"bodyForce"});
    EXPECT_FALSE(sys.hasVelocityDependentNonPairForces()) << "a body force does not read velocities";
}

TEST(ForceTerms, ABodyForceSetAfterInitialiseActs) {
    System sys = makeStandardFluid(smallFluid());
    sys.bodyForce = std::make_shared<UniformBodyForce>(Eigen::Vector3d(0.02, 0, 0));
    sys.computeForces();
    double sum = 0.0;
    for (std::size_t i = 0; i < sys.particles.size(); ++i) sum += sys.particles.fx[i];
    // The pair forces cancel in pairs (to round-off); the body force adds N g.
    EXPECT_NEAR(sum, 0.02 * static_cast<double>(sys.particles.size()), 1e-9);
}

TEST(ForceTerms, ChainsBringTheirBondsAndTakeBackTheBondedPairsShareOnlyWhereOneIsLeftOut) {
    const System keepsAll = test::makeChainedFluid(chainedFluid(BondedPairs::Mode::all));
    EXPECT_EQ(keepsAll.forceTermTypes(), (Types{"bodyForce", "bonds"}));
    EXPECT_FALSE(keepsAll.hasVelocityDependentNonPairForces());
    const System leavesOut = test::makeChainedFluid(chainedFluid(BondedPairs::Mode::none));
    EXPECT_EQ(leavesOut.forceTermTypes(), (Types{"bondedPairCorrection", "bodyForce", "bonds"}));
    EXPECT_TRUE(leavesOut.hasVelocityDependentNonPairForces()) << "the dissipative share taken back reads v";
}
