// Reading system/integratorSpeedAccuracyDict (studies/SpeedAccuracyStudy.cpp): a reference that is
// not one of the integrators, and a viscosity profile too coarse for the reverse-Poiseuille fit, are
// input errors naming the keyword; a good dictionary turns pressure sampling on and sets the viscosity
// probe.
#include "../support/InputErrorOf.hpp"
#include "core/Error.hpp"
#include "studies/SpeedAccuracyStudy.hpp"
#include "io/Dictionary.hpp"

#include <gtest/gtest.h>

#include <string>

using namespace dpd;

namespace {

const std::string kBase = "fluid { particles 648; density 3; }\n"
                          "integrators { GW { type GrootWarren; } VV { type DPDVV; } }\n"
                          "deltaT (0.01 0.02);\n"
                          "equilibrationTime 1; productionTime 10; blockTime 2;\n";

SpeedAccuracySettings read(const std::string& text) {
    return readSpeedAccuracySettings(Dictionary::parse(text, "system/integratorSpeedAccuracyDict"));
}

std::string errorOf(const std::string& text) {
    return test::inputErrorOf([&] { read(text); });
}

const std::string kViscosity = "viscosity { lengthRatio 2; g 0.05; bins 24; exclude 1; equilibrationTime 2; "
                               "productionTime 10; blockTime 2; }\n";

}  // namespace

TEST(SpeedAccuracySettings, ReadsReferencePressureAndViscosity) {
    const SpeedAccuracySettings s = read(kBase + "reference VV;\n" + kViscosity);
    EXPECT_EQ(s.reference, "VV");
    EXPECT_TRUE(s.probe.samplePressure);
    ASSERT_TRUE(s.viscosity);
    EXPECT_DOUBLE_EQ(s.viscosityLengthRatio, 2.0);
    EXPECT_DOUBLE_EQ(s.viscosityProbe.g, 0.05);
    EXPECT_EQ(s.viscosityProbe.bins, 24);
    EXPECT_EQ(s.viscosityProbe.run.blocks, 5);
    EXPECT_FALSE(read(kBase + "reference GW;\n").viscosity);
}

TEST(SpeedAccuracySettings, UnknownReferenceNamesTheKeyword) {
    const std::string e = errorOf(kBase + "reference Shardlow;\n");
    EXPECT_NE(e.find("reference"), std::string::npos) << e;
    EXPECT_NE(e.find("Shardlow"), std::string::npos) << e;
}

TEST(SpeedAccuracySettings, TooFewBinsForTheFitNamesTheKeyword) {
    // Lz = 12: halves of 6, less 2 x exclude 1 leaves 4; 6 bins of 2 leave two points per half.
    std::string v = kViscosity;
    v.replace(v.find("bins 24"), 7, "bins 6");
    const std::string e = errorOf(kBase + "reference VV;\n" + v);
    EXPECT_NE(e.find("bins"), std::string::npos) << e;
}

TEST(SpeedAccuracySettings, TheReferenceStepIsBelowEveryStudiedStep) {
    EXPECT_DOUBLE_EQ(read(kBase + "reference VV;\n").referenceDeltaT, 0.005);  // half the smallest
    EXPECT_DOUBLE_EQ(read(kBase + "reference VV;\nreferenceDeltaT 0.002;\n").referenceDeltaT, 0.002);
    for (const char* dt : {"0.01", "0.015", "0", "-0.001"}) {
        const std::string e = errorOf(kBase + "reference VV;\nreferenceDeltaT " + dt + ";\n");
        EXPECT_NE(e.find("referenceDeltaT"), std::string::npos) << dt << ": " << e;
        EXPECT_NE(e.find("its own reference"), std::string::npos) << dt << ": " << e;
    }
}
