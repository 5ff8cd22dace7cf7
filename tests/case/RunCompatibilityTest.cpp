// The one check pass over what a run's parts declare (case/RunCompatibility.*, core/Capabilities.hpp):
// each refusal the parts declare fires when, and only when, every feature it names is present, at the
// keyword that asked for the refused part, naming the parts that bring the features and the types
// that would run; the case's own parts are checked when dpdProperties is read.
#include "../support/InputErrorOf.hpp"
#include "case/DpdProperties.hpp"
#include "case/RunCompatibility.hpp"
#include "io/Dictionary.hpp"
#include "sampling/FunctionObjects.hpp"
#include "setup/StandardFluid.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

using namespace dpd;
using dpd::test::inputErrorOf;

namespace {

const std::string kFluid = "kT 1;\nspecies { fluid { frozen no; } }\npairCoeffs { fluid-fluid { a 25; gamma 4.5; } }\n";
const std::string kTunableWall =
    "walls { top { type plane; point (0 0 5); normal (0 0 -1); reflection bounceBack;\n"
    "    tunableSlip { gammaL 2; zc 1; epsilon 1; sigma 0.5; } } }\n";
const std::string kWeightedBonds = "bonds { type FENE; H 6; rMax 3; bondedPairs { dpd none; } }\n";
const std::string kStress = "profile { type binnedProfile; axis z; nBins 4; min -2; max 2; stress yes; flowAxis x; }";

DpdModel model(const std::string& integrator, const std::string& more) {
    return readDpdModel(Dictionary::parse(kFluid + "integrator { type " + integrator + "; }\n" + more, "constant/dpdProperties"));
}

std::string refusalOf(const std::string& integrator, const std::string& more) {
    return inputErrorOf([&] { model(integrator, more); });
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The parts of a run of the case on `ranks` ranks that samples with the function objects given.
std::string runRefusalOf(const DpdModel& m, int ranks, const std::string& functionsText) {
    StandardFluidSettings s;
    s.particles = 200;
    const System sys = makeStandardFluid(s);
    const Dictionary functions = Dictionary::parse(functionsText, "system/controlDict functions");
    const FunctionObjects objects = FunctionObjects::read(functions, sys);
    return inputErrorOf([&] {
        std::vector<RunPart> parts = caseParts(m);
        parts.push_back(ranksPart(ranks));
        for (RunPart& f : functionParts(objects, functions)) parts.push_back(std::move(f));
        checkCompatibility(parts);
    });
}

}  // namespace

// The Shardlow sweep has no place for a force besides the pair force that reads the velocities.
TEST(RunCompatibility, ShardlowRefusesAWallWithFriction) {
    const std::string e = refusalOf("Shardlow", kTunableWall);
    EXPECT_TRUE(contains(e, "keyword 'type'") && contains(e, "Shardlow") && contains(e, "wall 'top' (tunableSlip)")) << e;
    EXPECT_TRUE(contains(e, "use Euler, GrootWarren or DPDVV")) << e;
    for (const char* other : {"Euler", "GrootWarren", "DPDVV"}) EXPECT_EQ(refusalOf(other, kTunableWall), "") << other;
    EXPECT_EQ(refusalOf("Shardlow", ""), "");
}

// Taking back part of the pair force needs the whole pair force, which DPD-VV computes in parts; the
// share reads the velocities, which the Shardlow sweep cannot.
TEST(RunCompatibility, BondedPairsOtherThanAllNeedTheWholePairForce) {
    const std::string vv = refusalOf("DPDVV", kWeightedBonds);
    EXPECT_TRUE(contains(vv, "keyword 'type'") && contains(vv, "DPDVV") && contains(vv, "bondedPairs")) << vv;
    EXPECT_TRUE(contains(vv, "use Euler or GrootWarren")) << vv;
    EXPECT_TRUE(contains(refusalOf("Shardlow", kWeightedBonds), "Shardlow"));
    EXPECT_EQ(refusalOf("GrootWarren", kWeightedBonds), "");
    EXPECT_EQ(refusalOf("Euler", kWeightedBonds), "");
    EXPECT_EQ(refusalOf("DPDVV", "bonds { type FENE; H 6; rMax 3; }\n"), "") << "all of the pair force kept";
}

TEST(RunCompatibility, ShardlowRefusesSeveralRanks) {
    const DpdModel shardlow = model("Shardlow", "");
    const std::string e = runRefusalOf(shardlow, 2, "");
    EXPECT_TRUE(contains(e, "Shardlow cannot run on several ranks yet") && contains(e, "the run on 2 ranks")) << e;
    EXPECT_TRUE(contains(e, "use Euler, GrootWarren or DPDVV")) << e;
    EXPECT_EQ(runRefusalOf(shardlow, 1, ""), "");
    EXPECT_EQ(runRefusalOf(model("DPDVV", ""), 2, ""), "");
}

// The stress is the virial of the whole pair force; on several ranks a crossing completed after the
// sort must not carry a particle past a slab's face: two features that refuse only together.
TEST(RunCompatibility, TheStressSamplerSaysWhatItCannotSample) {
    const std::string bonds = runRefusalOf(model("GrootWarren", kWeightedBonds), 1, kStress);
    EXPECT_TRUE(contains(bonds, "system/controlDict functions") && contains(bonds, "keyword 'stress'") &&
                contains(bonds, "function object 'profile'") && contains(bonds, "bondedPairs")) << bonds;
    const std::string sideWall =
        "walls { side { type plane; point (-4.5 0 0); normal (1 0 0); reflection bounceForward; } }\n";
    const DpdModel facingX = model("GrootWarren", sideWall);
    const std::string ranks = runRefusalOf(facingX, 2, kStress);
    EXPECT_TRUE(contains(ranks, "keyword 'stress'") && contains(ranks, "cannot sample the stress on several ranks") &&
                contains(ranks, "the run on 2 ranks") && contains(ranks, "wall 'side'")) << ranks;
    EXPECT_EQ(runRefusalOf(facingX, 1, kStress), "") << "one rank";
    const std::string noStress = "profile { type binnedProfile; axis z; nBins 4; min -2; max 2; }";
    EXPECT_EQ(runRefusalOf(facingX, 2, noStress), "") << "no stress";
    EXPECT_EQ(runRefusalOf(model("GrootWarren", kWeightedBonds), 1, noStress), "") << "no stress";
    const std::string facingZ = "walls { top { type plane; point (0 0 4.5); normal (0 0 -1); reflection bounceForward; } }\n";
    EXPECT_EQ(runRefusalOf(model("GrootWarren", facingZ), 2, kStress), "") << "crossings along z stay in their slab";
}

// A refusal of two features needs both; a part that refuses names the entry that asked for it.
TEST(RunCompatibility, ARefusalFiresOnlyWhenAllItsFeaturesArePresent) {
    const Dictionary entry = Dictionary::parse("sampler { type probe; }", "system/controlDict");
    const RunPart refuser{"probe", {{}, {{{Feature::severalRanks, Feature::velocityForce}, "cannot run here", ""}}},
                          &entry.subDict("sampler"), "type", {}};
    const RunPart ranks{"ranks", {{Feature::severalRanks}, {}}, nullptr, "", {}};
    const RunPart friction{"friction", {{Feature::velocityForce}, {}}, nullptr, "", {}};
    EXPECT_NO_THROW(checkCompatibility({refuser, ranks}));
    EXPECT_NO_THROW(checkCompatibility({refuser, friction}));
    const std::string e = inputErrorOf([&] { checkCompatibility({refuser, ranks, friction}); });
    EXPECT_TRUE(contains(e, "probe cannot run here (with ranks and friction)") && contains(e, "keyword 'type'")) << e;
    RunPart nowhere = refuser;
    nowhere.where = nullptr;
    EXPECT_THROW(checkCompatibility({nowhere, ranks, friction}), std::logic_error);
}
