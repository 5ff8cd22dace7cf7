// Body forces (forces/BodyForce.*, BodyForceTypes.cpp): chosen by name, each type reading its own
// keywords, and the force each adds: g on every mobile particle (uniform), +g below and -g above the
// middle of the box along the gradient axis (reverse Poiseuille), nothing on a frozen particle.
#include "core/Error.hpp"
#include "forces/BodyForce.hpp"
#include "forces/ReversePoiseuilleBodyForce.hpp"
#include "forces/UniformBodyForce.hpp"
#include "io/Dictionary.hpp"

#include <gtest/gtest.h>

#include <string>

using namespace dpd;

namespace {

std::shared_ptr<const BodyForce> read(const std::string& block, int dimension = 3) {
    return readBodyForce(Dictionary::parse("bodyForce\n{\n" + block + "\n}\n", "constant/dpdProperties"), dimension);
}

// The keyword and line of the error a bodyForce block gets ("" when it is read).
std::string refusal(const std::string& block, int dimension = 3) {
    try {
        read(block, dimension);
    } catch (const InputError& e) {
        return e.keyword() + ":" + std::to_string(e.line());
    }
    return "";
}

// Three particles at z = 1, 6 and 8 in a box 0..10; the last one frozen (species 1).
Particles threeParticles() {
    Particles p;
    p.add(0, 0, 5, 5, 1);
    p.add(1, 0, 5, 5, 6);
    p.add(2, 1, 5, 5, 8);
    return p;
}

}  // namespace

TEST(BodyForce, TypesAreChosenByNameAndReadTheirOwnKeywords) {
    EXPECT_EQ(readBodyForce(Dictionary::parse("kT 1;", "constant/dpdProperties"), 3)->typeName(), "none");
    EXPECT_EQ(read("type none;")->typeName(), "none");
    const auto u = read("type uniform; value (0.02 0 0);");
    EXPECT_EQ(u->typeName(), "uniform");
    EXPECT_TRUE(u->uniform());
    EXPECT_EQ(u->value(), Eigen::Vector3d(0.02, 0, 0));
    const auto r = read("type reversePoiseuille; value (0.05 0 0); gradientAxis z;");
    EXPECT_EQ(r->typeName(), "reversePoiseuille");
    EXPECT_FALSE(r->uniform());
    EXPECT_EQ(r->gradientAxis(), 2);
    // Each refusal names its keyword on line 3 (the block's body).
    EXPECT_EQ(refusal("type gravity; value (0 0 -1);"), "type:3");
    EXPECT_EQ(refusal("type uniform; value (0.02 0 0); gradientAxis z;"), "gradientAxis:3") << "not a uniform force's";
    EXPECT_EQ(refusal("type none; value (0.02 0 0);"), "value:3");
    EXPECT_EQ(refusal("type reversePoiseuille; value (0.05 0 0.1); gradientAxis z;"), "value:3") << "along the gradient";
    EXPECT_EQ(refusal("type uniform; value (0 0.02 0);", 2), "value:3") << "2-D lies in the x-z plane";
    EXPECT_EQ(refusal("type uniform;"), "value:1") << "a missing keyword is named at the block's line";
}

TEST(BodyForce, EachTypeAddsItsForceToTheMobileParticlesOnly) {
    const Box box{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(10, 10, 10), 3};
    const std::vector<std::uint8_t> frozen{0, 1};
    Particles p = threeParticles();
    UniformBodyForce(Eigen::Vector3d(0.1, -0.2, 0.3)).apply(p, frozen, box);
    for (int i = 0; i < 2; ++i) {
        EXPECT_EQ(p.fx[i], 0.1);
        EXPECT_EQ(p.fy[i], -0.2);
        EXPECT_EQ(p.fz[i], 0.3);
    }
    EXPECT_EQ(p.fx[2], 0.0) << "frozen";
    p = threeParticles();
    ReversePoiseuilleBodyForce(Eigen::Vector3d(0.5, 0, 0), 2).apply(p, frozen, box);
    EXPECT_EQ(p.fx[0], 0.5) << "z = 1: lower half";
    EXPECT_EQ(p.fx[1], -0.5) << "z = 6: upper half";
    EXPECT_EQ(p.fx[2], 0.0) << "frozen";
    EXPECT_FALSE(noBodyForce()->active());
}
