// Choosing the integrator in constant/dpdProperties (case/DpdProperties.cpp, integrators/Integrator.cpp):
// every listed type builds the scheme of that name, and a wrong type or a misplaced lambda is an input
// error naming the file, the line and the keyword, and listing the valid types.
#include "core/Error.hpp"
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
    EXPECT_DOUBLE_EQ(readWithIntegrator("type GrootWarren; lambda 0.5;").integrator.lambda, 0.5);
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
