// The builders' `box` entry (case/BoxDictionary.*): a periodic axis two cutoffs long is taken (the
// published porous medium's box is 2 thick), a shorter one is refused naming the file, line and keyword.
#include "case/BoxDictionary.hpp"
#include "core/Error.hpp"
#include "io/Dictionary.hpp"

#include <gtest/gtest.h>

#include <string>

using namespace dpd;

namespace {

Box readBox(const std::string& text, int dimension = 3, double cutoff = 1.0) {
    return readBoxDictionary(Dictionary::parse(text, "system/randomEquilWallDict"), dimension, cutoff);
}

}  // namespace

TEST(BoxDictionary, TakesAnAxisTwoCutoffsLong) {
    const Box box = readBox("box { min (-80 -1 -80); max (80 1 80); }");
    EXPECT_DOUBLE_EQ(box.length().y(), 2.0);
    EXPECT_DOUBLE_EQ(box.length().x(), 160.0);
    EXPECT_NO_THROW(readBox("box { min (0 0 0); max (3 3 3); }", 3, 1.5));
}

TEST(BoxDictionary, RefusesAnAxisShorterThanTwoCutoffsNamingIt) {
    try {
        readBox("box\n{\n    min (0 0 0);\n    max (5 1.9 5);\n}\n");
        FAIL() << "a box 1.9 long along y was taken";
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), "system/randomEquilWallDict");
        EXPECT_EQ(e.keyword(), "max");
        EXPECT_EQ(e.line(), 4);
        EXPECT_NE(std::string(e.what()).find("at least two cutoffs long along y"), std::string::npos) << e.what();
    }
    EXPECT_THROW(readBox("box { min (0 0 0); max (5 5 3.9); }", 3, 2.0), InputError);
    // 2-D: y is inactive and takes any extent; x and z still need two cutoffs.
    EXPECT_NO_THROW(readBox("box { min (0 0 0); max (5 0.1 5); }", 2));
    EXPECT_THROW(readBox("box { min (0 0 0); max (1.5 1 5); }", 2), InputError);
}
