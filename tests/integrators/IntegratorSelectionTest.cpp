// Choosing the integrator by name (integrators/Integrator.*, IntegratorTypes.cpp): every listed type
// builds the scheme of that name from its own sub-dictionary, a wrong type or a misplaced lambda is an
// input error naming the file, the line and the keyword (and the valid types). What a type cannot run
// beside is the check pass's (tests/case/RunCompatibilityTest.cpp).
#include "core/Error.hpp"
#include "integrators/EulerIntegrator.hpp"
#include "integrators/GrootWarrenIntegrator.hpp"
#include "integrators/Integrator.hpp"
#include "io/Dictionary.hpp"
#include "case/DpdProperties.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

using namespace dpd;

namespace {

DpdModel readWithIntegrator(const std::string& integratorEntry) {
    const std::string text = "kT 1;\nspecies { fluid { frozen no; } }\n"
                             "pairCoeffs { fluid-fluid { a 25; gamma 4.5; } }\n"
                             "integrator\n{\n" + integratorEntry + "\n}\n";
    return readDpdModel(Dictionary::parse(text, "constant/dpdProperties"));
}

}  // namespace

TEST(IntegratorSelection, EveryTypeBuildsTheSchemeOfThatName) {
    EXPECT_EQ(integratorTypes(), (std::vector<std::string>{"Euler", "GrootWarren", "DPDVV", "Shardlow"}));
    for (const std::string& type : integratorTypes()) {
        const DpdModel m = readWithIntegrator("type " + type + ";");
        EXPECT_EQ(m.integrator.type, type);
        EXPECT_EQ(makeIntegrator(m.integrator)->name(), type);
    }
    const auto gw = makeIntegrator(readWithIntegrator("type GrootWarren; lambda 0.5;").integrator);
    EXPECT_DOUBLE_EQ(dynamic_cast<const GrootWarrenIntegrator&>(*gw).lambda(), 0.5);
    EXPECT_DOUBLE_EQ(dynamic_cast<const GrootWarrenIntegrator&>(*makeIntegrator(IntegratorSettings{})).lambda(), 0.65);
}

TEST(IntegratorSelection, UnknownTypeNamesFileLineAndTheValidTypes) {
    try {
        readWithIntegrator("type Verlet;");
        FAIL() << "an unknown type must be refused";
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), "constant/dpdProperties");
        EXPECT_EQ(e.line(), 6);
        EXPECT_EQ(e.keyword(), "type");
        EXPECT_NE(std::string(e.what()).find("'Verlet'"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("Euler, GrootWarren, DPDVV or Shardlow"), std::string::npos) << e.what();
    }
    IntegratorSettings s;
    s.type = "Verlet";
    EXPECT_THROW(makeIntegrator(s), std::invalid_argument);
}

TEST(IntegratorSelection, LambdaBelongsToGrootWarrenOnly) {
    for (const std::string type : {"Euler", "DPDVV", "Shardlow"}) {
        try {
            readWithIntegrator("type " + type + "; lambda 0.6;");
            FAIL() << type << " must refuse lambda";
        } catch (const InputError& e) {
            EXPECT_EQ(e.keyword(), "lambda");
        }
    }
    EXPECT_THROW(readWithIntegrator("type GrootWarren; lambda 1.5;"), InputError);
}

// The registry refuses a name twice and lists the names in order.
TEST(IntegratorSelection, TheRegistryKeepsOneMakerPerName) {
    IntegratorRegistry r;
    r.add("A", &EulerIntegrator::New).add("B", &EulerIntegrator::New).add("C", &EulerIntegrator::New);
    EXPECT_EQ(r.nameList(), "A, B or C");
    EXPECT_THROW(r.add("B", &EulerIntegrator::New), std::logic_error);
    EXPECT_THROW(r.make("D", Dictionary("x")), std::invalid_argument);
    EXPECT_EQ(r.make("C", Dictionary("x"))->name(), "Euler");
}
