// Slip lever a_wf (docs/methods.md section 1 and docs/walls.md 3.4): an unlike pair of constant/dpdProperties that is
// left out, or given without `a`, is mixed from the like pairs as a_wf = sqrt(a_ww a_ff), and the log
// notes say so; a pair that cannot be determined is an error naming the file and the pair.
#include "../support/InputErrorOf.hpp"
#include "core/Error.hpp"
#include "io/Dictionary.hpp"
#include "case/DpdProperties.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace dpd;

namespace {

DpdModel model(const std::string& pairs) {
    const std::string text = "FoamFile { version 2.0; format ascii; class dictionary; object dpdProperties; }\n"
                             "kT 1;\nspecies { fluid { frozen no; } wall { frozen yes; } }\n"
                             "pairCoeffs { " + pairs + " }\n";
    return readDpdModel(Dictionary::parse(text, "constant/dpdProperties"));
}

std::string inputError(const std::string& pairs) {
    return test::inputErrorOf([&] { model(pairs); });
}

}  // namespace

TEST(PairMixing, MissingUnlikePairIsMixedFromTheLikePairs) {
    const DpdModel m = model("fluid-fluid { a 18.75; gamma 4.5; } wall-wall { a 5; gamma 4.5; }");
    const int f = m.species.indexOf("fluid"), w = m.species.indexOf("wall");
    EXPECT_DOUBLE_EQ(m.pairs(f, w).a, std::sqrt(18.75 * 5.0));
    EXPECT_DOUBLE_EQ(m.pairs(w, f).a, std::sqrt(18.75 * 5.0));
    EXPECT_DOUBLE_EQ(m.pairs(f, w).gamma, 4.5);  // sqrt(4.5 x 4.5)
    ASSERT_EQ(m.pairNotes.size(), 1u);
    EXPECT_NE(m.pairNotes[0].find("fluid-wall"), std::string::npos) << m.pairNotes[0];
    EXPECT_NE(m.pairNotes[0].find("mixed"), std::string::npos) << m.pairNotes[0];
}

TEST(PairMixing, UnlikePairWithGammaOnlyMixesA) {
    // The gamma_fw lever and the a_wf lever together: gamma given, a mixed.
    const DpdModel m = model("fluid-fluid { a 18.75; gamma 4.5; } wall-wall { a 15; gamma 4.5; } fluid-wall { gamma 13.5; }");
    const int f = m.species.indexOf("fluid"), w = m.species.indexOf("wall");
    EXPECT_DOUBLE_EQ(m.pairs(f, w).a, std::sqrt(18.75 * 15.0));
    EXPECT_DOUBLE_EQ(m.pairs(f, w).gamma, 13.5);
}

TEST(PairMixing, GivenPairsAreKeptAndNotNoted) {
    const DpdModel m = model("fluid-fluid { a 18.75; gamma 4.5; } fluid-wall { a 30; gamma 2; }");
    const int f = m.species.indexOf("fluid"), w = m.species.indexOf("wall");
    EXPECT_DOUBLE_EQ(m.pairs(f, w).a, 30.0);
    EXPECT_DOUBLE_EQ(m.pairs(f, w).gamma, 2.0);
    EXPECT_TRUE(m.pairNotes.empty());
}

TEST(PairMixing, UndeterminedPairIsAClearError) {
    // No fluid-wall and no wall-wall: nothing to mix from.
    const std::string e = inputError("fluid-fluid { a 18.75; gamma 4.5; }");
    EXPECT_NE(e.find("constant/dpdProperties"), std::string::npos) << e;
    EXPECT_NE(e.find("fluid-wall"), std::string::npos) << e;
    EXPECT_NE(e.find("wall-wall"), std::string::npos) << e;
    // A like pair cannot be mixed: it needs its own a.
    EXPECT_NE(inputError("fluid-fluid { gamma 4.5; } wall-wall { a 5; gamma 4.5; }").find("like pair"), std::string::npos);
    // Negative like-pair a: no real geometric mean.
    EXPECT_NE(inputError("fluid-fluid { a 18.75; gamma 4.5; } wall-wall { a -5; gamma 4.5; }").find("negative"),
              std::string::npos);
}
