// Tests of the OpenFOAM-syntax dictionary reader/writer (libdpd/io/Dictionary.hpp).
#include "io/Dictionary.hpp"

#include "core/Error.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include <unistd.h>

namespace fs = std::filesystem;
using dpd::Dictionary;
using dpd::InputError;

namespace {

// Runs f, which must throw InputError, and checks that the error names the file, the line (0: no
// line) and the keyword ("" : none). Returns the message for further checks.
std::string expectInputError(const std::function<void()>& f, const std::string& file, int line,
                             const std::string& keyword) {
    try {
        f();
    } catch (const InputError& e) {
        const std::string msg = e.what();
        EXPECT_EQ(e.file(), file) << msg;
        EXPECT_EQ(e.line(), line) << msg;
        EXPECT_EQ(e.keyword(), keyword) << msg;
        const std::string where = line > 0 ? file + ":" + std::to_string(line) + ":" : file + ":";
        EXPECT_EQ(msg.rfind(where, 0), 0u) << "message should start with '" << where << "': " << msg;
        if (!keyword.empty()) {
            EXPECT_NE(msg.find("keyword '" + keyword + "'"), std::string::npos) << msg;
        }
        return msg;
    }
    ADD_FAILURE() << "expected an InputError";
    return "";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// A fresh directory per test, removed afterwards.
class DictionaryFiles : public ::testing::Test {
protected:
    void SetUp() override {
        static int counter = 0;
        dir_ = fs::path(::testing::TempDir()) /
               ("dictionaryTest_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    std::string write(const std::string& name, const std::string& text) const {
        const fs::path p = dir_ / name;
        fs::create_directories(p.parent_path());
        std::ofstream(p) << text;
        return p.string();
    }
    std::string pathOf(const std::string& name) const { return (dir_ / name).string(); }

    fs::path dir_;
};

const char* const kControlDict = R"(/*---------------------------------*- C++ -*---*\
  a banner comment
\*-----------------------------------------------*/
FoamFile
{
    version     2.0;
    format      ascii;
    class       dictionary;
    object      controlDict;
}

application     dpdFoam;       // a word
deltaT          0.02;
endTime         100;
tolerance       -1e-3;
title           "a b";
model           GrootWarren;
pair            fluid-wall;
writeFormat     binary;
)";

}  // namespace

// ---- syntax ------------------------------------------------------------------------------------

TEST(DictionaryParse, HeaderWordsNumbersAndStrings) {
    const Dictionary d = Dictionary::parse(kControlDict, "system/controlDict");
    EXPECT_EQ(d.fileName(), "system/controlDict");
    EXPECT_EQ(d.line(), 0);
    EXPECT_EQ(d.path(), "");
    EXPECT_EQ(d.get<std::string>("application"), "dpdFoam");
    EXPECT_DOUBLE_EQ(d.get<double>("deltaT"), 0.02);
    EXPECT_EQ(d.get<int>("endTime"), 100);
    EXPECT_EQ(d.get<long>("endTime"), 100L);
    EXPECT_EQ(d.get<std::int64_t>("endTime"), std::int64_t{100});
    EXPECT_DOUBLE_EQ(d.get<double>("endTime"), 100.0);
    EXPECT_DOUBLE_EQ(d.get<double>("tolerance"), -1e-3);
    EXPECT_EQ(d.get<std::string>("title"), "a b");
    EXPECT_EQ(d.get<std::string>("pair"), "fluid-wall");
    EXPECT_EQ(d.lineOf("deltaT"), 13);
    // The header stays reachable but is no keyword of the case.
    EXPECT_TRUE(d.found("FoamFile"));
    EXPECT_EQ(d.subDict("FoamFile").get<std::string>("object"), "controlDict");
    EXPECT_EQ(d.keys(), (std::vector<std::string>{"application", "deltaT", "endTime", "tolerance", "title",
                                                  "model", "pair", "writeFormat"}));
    EXPECT_NO_THROW(d.checkKeys(d.keys()));
}

TEST(DictionaryParse, Lists) {
    const Dictionary d = Dictionary::parse(R"(
origin      (0.02 0 0);
fractions   (0.15 0.35 0.75);
segments    ((0 0) (1 1));
species     (fluid wall "frozen wall");
counted     3(1 2 3);
ints        (1 -2 3);
points
(
    (0 0 0)
    (1 0 0)   // comment inside a list
);
empty       ();
)",
                                           "lists");
    EXPECT_EQ(d.get<Eigen::Vector3d>("origin"), Eigen::Vector3d(0.02, 0, 0));
    EXPECT_EQ(d.get<std::vector<double>>("fractions"), (std::vector<double>{0.15, 0.35, 0.75}));
    EXPECT_EQ(d.get<std::vector<std::vector<double>>>("segments"),
              (std::vector<std::vector<double>>{{0, 0}, {1, 1}}));
    EXPECT_EQ(d.get<std::vector<std::string>>("species"),
              (std::vector<std::string>{"fluid", "wall", "frozen wall"}));
    EXPECT_EQ(d.get<std::vector<double>>("counted"), (std::vector<double>{1, 2, 3}));
    EXPECT_EQ(d.get<std::vector<int>>("ints"), (std::vector<int>{1, -2, 3}));
    const auto points = d.get<std::vector<Eigen::Vector3d>>("points");
    ASSERT_EQ(points.size(), 2u);
    EXPECT_EQ(points[1], Eigen::Vector3d(1, 0, 0));
    EXPECT_EQ(d.lineOf("points"), 8);
    EXPECT_TRUE(d.get<std::vector<double>>("empty").empty());
    EXPECT_EQ(d.rawValue("segments"), "((0 0) (1 1))");
}

TEST(DictionaryParse, NestedSubDictionaries) {
    const Dictionary d = Dictionary::parse(R"(walls
{
    lower
    {
        velocity (1 0 0);
        deep { deeper { x 1; } }
    }
    upper { velocity (-1 0 0); }
};
after 2;
)",
                                           "constant/wallProperties");
    ASSERT_TRUE(d.isDict("walls"));
    EXPECT_FALSE(d.isDict("after"));
    EXPECT_FALSE(d.isDict("nothing"));
    const Dictionary& lower = d.subDict("walls").subDict("lower");
    EXPECT_EQ(lower.path(), "walls/lower");
    EXPECT_EQ(lower.line(), 3);
    EXPECT_EQ(lower.fileName(), "constant/wallProperties");
    EXPECT_EQ(lower.lineOf("velocity"), 5);
    EXPECT_EQ(lower.get<Eigen::Vector3d>("velocity"), Eigen::Vector3d(1, 0, 0));
    EXPECT_EQ(lower.subDict("deep").subDict("deeper").path(), "walls/lower/deep/deeper");
    EXPECT_EQ(lower.subDict("deep").subDict("deeper").get<int>("x"), 1);
    EXPECT_EQ(d.subDict("walls").keys(), (std::vector<std::string>{"lower", "upper"}));
    EXPECT_EQ(d.get<int>("after"), 2);
    EXPECT_EQ(d.lineOf("after"), 10);
}

TEST(DictionaryParse, Comments) {
    const Dictionary d = Dictionary::parse(R"(// line comment
a 1.5;// no space before the comment
/* block
   comment with ; and { and "
*/ b /* inline */ 2/*adjacent*/;
c (1 /* x */ 2 3);
url "http://not/a/comment";
)",
                                           "comments");
    EXPECT_DOUBLE_EQ(d.get<double>("a"), 1.5);
    EXPECT_EQ(d.get<int>("b"), 2);
    EXPECT_EQ(d.lineOf("b"), 5);
    EXPECT_EQ(d.get<std::vector<int>>("c"), (std::vector<int>{1, 2, 3}));
    EXPECT_EQ(d.get<std::string>("url"), "http://not/a/comment");
    EXPECT_EQ(d.keys(), (std::vector<std::string>{"a", "b", "c", "url"}));
}

TEST(DictionaryParse, LaterDuplicateOverrides) {
    const Dictionary d = Dictionary::parse(R"(a 1;
b 2;
a 3;
sub { x 1; y 2; }
sub { y 5; z 6; }
)",
                                           "dups");
    EXPECT_EQ(d.get<int>("a"), 3);
    EXPECT_EQ(d.lineOf("a"), 3);
    EXPECT_EQ(d.keys(), (std::vector<std::string>{"a", "b", "sub"}));
    // Two sub-dictionaries merge keyword by keyword (OpenFOAM's default input mode).
    const Dictionary& sub = d.subDict("sub");
    EXPECT_EQ(sub.get<int>("x"), 1);
    EXPECT_EQ(sub.get<int>("y"), 5);
    EXPECT_EQ(sub.get<int>("z"), 6);
    // Both are taken, but neither silently: each repetition is a warning naming both lines.
    ASSERT_EQ(d.warnings().size(), 2u);
    EXPECT_EQ(d.warnings()[0], "dups:3: keyword 'a' given twice (lines 1 and 3): the last one is used");
    EXPECT_EQ(d.warnings()[1], "dups:5: keyword 'sub' given twice (lines 4 and 5): the two are merged");
    const Dictionary nested = Dictionary::parse("walls\n{\n  lower { a 1;\n  a 2; }\n}\n", "n");
    ASSERT_EQ(nested.warnings().size(), 1u);
    EXPECT_EQ(nested.warnings()[0], "n:4: keyword 'a' given twice in walls/lower (lines 3 and 4): the last one is used");
    EXPECT_TRUE(Dictionary::parse("a 1;\nb { a 2; }\n", "x").warnings().empty()) << "one per dictionary";
}

// Nesting deeper than any case needs is refused at the line where it goes too deep, not followed
// until the stack runs out.
TEST(DictionaryParse, DeepNestingIsRefused) {
    std::string dicts, lists = "a ";
    for (int k = 0; k < 100000; ++k) dicts += "d {\n";
    for (int k = 0; k < 100000; ++k) lists += "(";
    const std::string msg = expectInputError([&] { Dictionary::parse(dicts, "deep"); }, "deep", 65, "d");
    EXPECT_TRUE(contains(msg, "nested more than 64")) << msg;
    expectInputError([&] { Dictionary::parse(lists, "lists"); }, "lists", 1, "a");
    std::string ok;
    for (int k = 0; k < 60; ++k) ok += "d { ";
    ok += "x 1;";
    for (int k = 0; k < 60; ++k) ok += " }";
    EXPECT_NO_THROW(Dictionary::parse(ok, "ok"));
}

TEST(DictionaryParse, QuotedStringsAndEmptyValues) {
    const Dictionary d = Dictionary::parse(R"(q "say \"hi\" \\ back";
"quoted key" 1;
flag;
)",
                                           "strings");
    EXPECT_EQ(d.get<std::string>("q"), "say \"hi\" \\ back");
    EXPECT_EQ(d.get<int>("quoted key"), 1);
    EXPECT_TRUE(d.found("flag"));
    EXPECT_EQ(d.rawValue("flag"), "");
}

TEST(DictionaryParse, Switches) {
    const Dictionary d =
        Dictionary::parse("a yes; b no; c on; d off; e true; f false; g maybe; h 1;", "switches");
    EXPECT_TRUE(d.get<bool>("a"));
    EXPECT_FALSE(d.get<bool>("b"));
    EXPECT_TRUE(d.get<bool>("c"));
    EXPECT_FALSE(d.get<bool>("d"));
    EXPECT_TRUE(d.get<bool>("e"));
    EXPECT_FALSE(d.get<bool>("f"));
    const std::string msg = expectInputError([&] { d.get<bool>("g"); }, "switches", 1, "g");
    EXPECT_TRUE(contains(msg, "yes/no")) << msg;
    expectInputError([&] { d.get<bool>("h"); }, "switches", 1, "h");
}

TEST(DictionaryParse, Defaults) {
    const Dictionary d = Dictionary::parse("a 2;\nsub { }\n", "defaults");
    EXPECT_EQ(d.getOrDefault("a", 7), 2);
    EXPECT_EQ(d.getOrDefault("missing", 7), 7);
    EXPECT_EQ(d.getOrDefault("missing", "word"), "word");
    EXPECT_EQ(d.getOrDefault<std::string>("missing", "x"), "x");
    EXPECT_TRUE(d.subDict("sub").keys().empty());
    // A default does not hide a wrong type.
    expectInputError([&] { d.getOrDefault<std::string>("sub", "x"); }, "defaults", 2, "sub");
}

// ---- macros ------------------------------------------------------------------------------------

TEST(DictionaryMacro, ValueSubstitution) {
    const Dictionary d = Dictionary::parse(R"(rc 1.5;
u (1 0 0);
walls
{
    cutoff $rc;            // enclosing scope
    lower { velocity $u; speed 2; }
    local 4;
    inner { v $local; w $lower.speed; }
}
copied  $walls.lower.velocity;
top     $:walls.inner.v;
braces  ${rc};
inList  ($rc 0 $rc);
rc 3;                      // later changes do not reach earlier uses
)",
                                           "macros");
    EXPECT_DOUBLE_EQ(d.subDict("walls").get<double>("cutoff"), 1.5);
    EXPECT_EQ(d.subDict("walls").subDict("lower").get<Eigen::Vector3d>("velocity"), Eigen::Vector3d(1, 0, 0));
    EXPECT_EQ(d.subDict("walls").subDict("inner").get<int>("v"), 4);
    EXPECT_EQ(d.subDict("walls").subDict("inner").get<int>("w"), 2);
    EXPECT_EQ(d.get<Eigen::Vector3d>("copied"), Eigen::Vector3d(1, 0, 0));
    EXPECT_EQ(d.get<int>("top"), 4);
    EXPECT_DOUBLE_EQ(d.get<double>("braces"), 1.5);
    EXPECT_EQ(d.get<std::vector<double>>("inList"), (std::vector<double>{1.5, 0, 1.5}));
    EXPECT_EQ(d.get<int>("rc"), 3);
}

TEST(DictionaryMacro, SubDictionaryCopyAndMerge) {
    const Dictionary d = Dictionary::parse(R"(defaults { a 25; gamma 4.5; }
pairs
{
    fluid-fluid $defaults;
    fluid-wall  { $defaults; a 50; }
}
)",
                                           "pairs");
    const Dictionary& ff = d.subDict("pairs").subDict("fluid-fluid");
    EXPECT_EQ(ff.get<int>("a"), 25);
    EXPECT_EQ(ff.path(), "pairs/fluid-fluid");
    EXPECT_EQ(ff.line(), 4);
    const Dictionary& fw = d.subDict("pairs").subDict("fluid-wall");
    EXPECT_EQ(fw.get<int>("a"), 50);
    EXPECT_DOUBLE_EQ(fw.get<double>("gamma"), 4.5);
    EXPECT_EQ(fw.keys(), (std::vector<std::string>{"a", "gamma"}));
}

TEST(DictionaryMacro, UnknownMacroNamesFileLineAndKeyword) {
    const std::string text = "a 1;\nsub\n{\n    b $nothing;\n}\n";
    const std::string msg = expectInputError([&] { Dictionary::parse(text, "caseDict"); }, "caseDict", 4, "b");
    EXPECT_TRUE(contains(msg, "$nothing")) << msg;
    // A macro is looked up only above its use.
    expectInputError([] { Dictionary::parse("a $b;\nb 1;\n", "order"); }, "order", 1, "a");
    expectInputError([] { Dictionary::parse("x 1;\n$x;\n", "entryForm"); }, "entryForm", 2, "$x");
}

TEST(DictionaryMacro, DictionaryMacroInsideValueIsAnError) {
    expectInputError([] { Dictionary::parse("s { a 1; }\nv (1 $s);\n", "m"); }, "m", 2, "v");
}

// ---- #include ----------------------------------------------------------------------------------

TEST_F(DictionaryFiles, IncludeRelativeToIncludingFile) {
    write("system/common/defaults", R"(FoamFile { version 2.0; format ascii; class dictionary; object defaults; }
deltaT 0.01;
nu 0.5;
bad abc;
)");
    write("system/common/walls", "velocity (2 0 0);\n");
    const std::string main = write("system/controlDict", R"(#include "common/defaults"
nu 0.7;              // overrides the included value
walls { #include "common/walls" }
vel $walls.velocity;
#includeIfPresent "common/optional"
)");
    const Dictionary d = Dictionary::readFile(main);
    EXPECT_DOUBLE_EQ(d.get<double>("deltaT"), 0.01);
    EXPECT_DOUBLE_EQ(d.get<double>("nu"), 0.7);
    EXPECT_FALSE(d.found("FoamFile"));  // the included file's header is dropped
    EXPECT_EQ(d.keys(), (std::vector<std::string>{"deltaT", "nu", "bad", "walls", "vel"}));
    EXPECT_EQ(d.subDict("walls").get<Eigen::Vector3d>("velocity"), Eigen::Vector3d(2, 0, 0));
    EXPECT_EQ(d.get<Eigen::Vector3d>("vel"), Eigen::Vector3d(2, 0, 0));
    // Errors about included entries name the included file and its line.
    expectInputError([&] { d.get<double>("bad"); }, pathOf("system/common/defaults"), 4, "bad");
    EXPECT_EQ(d.lineOf("deltaT"), 2);
    EXPECT_TRUE(d.warnings().empty()) << "an included default overridden is no slip";
}

TEST_F(DictionaryFiles, RepeatedKeywordsAreWarnedAboutOnStderr) {
    const std::string main = write("dpdProperties", "kT 1;\nseed 2;\nkT 1.5;\n");
    ::testing::internal::CaptureStderr();
    const Dictionary d = Dictionary::readFile(main);
    const std::string err = ::testing::internal::GetCapturedStderr();
    EXPECT_EQ(d.get<double>("kT"), 1.5);
    EXPECT_EQ(err, "Warning: " + main + ":3: keyword 'kT' given twice (lines 1 and 3): the last one is used\n");
}

TEST_F(DictionaryFiles, MissingIncludeNamesIncludingFileAndLine) {
    const std::string main = write("controlDict", "a 1;\n\n#include \"nowhere\"\n");
    const std::string msg = expectInputError([&] { Dictionary::readFile(main); }, main, 3, "#include");
    EXPECT_TRUE(contains(msg, "nowhere")) << msg;
}

TEST_F(DictionaryFiles, IncludeLoopIsAnError) {
    const std::string main = write("loop", "a 1;\n#include \"loop\"\n");
    expectInputError([&] { Dictionary::readFile(main); }, main, 2, "#include");
}

TEST_F(DictionaryFiles, SyntaxErrorInIncludedFileNamesThatFile) {
    const std::string inc = write("inc", "x 1;\n}\n");
    const std::string main = write("main", "#include \"inc\"\n");
    expectInputError([&] { Dictionary::readFile(main); }, inc, 2, "");
}

TEST_F(DictionaryFiles, MissingFile) {
    const std::string missing = pathOf("noSuchFile");
    const std::string msg = expectInputError([&] { Dictionary::readFile(missing); }, missing, 0, "");
    EXPECT_TRUE(contains(msg, "cannot open file")) << msg;
    expectInputError([&] { Dictionary::readFile(dir_.string()); }, dir_.string(), 0, "");  // a directory
}

// ---- errors ------------------------------------------------------------------------------------

TEST(DictionaryErrors, MissingKeyword) {
    const Dictionary d = Dictionary::parse("a 1;\n\nwalls\n{\n    x 1;\n}\n", "system/dpdDict");
    std::string msg = expectInputError([&] { d.get<double>("deltaT"); }, "system/dpdDict", 0, "deltaT");
    EXPECT_TRUE(contains(msg, "missing keyword")) << msg;
    EXPECT_TRUE(contains(msg, "a number")) << msg;
    // In a sub-dictionary: the line where it opened, and its scope.
    msg = expectInputError([&] { d.subDict("walls").get<Eigen::Vector3d>("velocity"); }, "system/dpdDict", 3,
                           "velocity");
    EXPECT_TRUE(contains(msg, "walls")) << msg;
    expectInputError([&] { d.subDict("lower"); }, "system/dpdDict", 0, "lower");
    expectInputError([&] { d.lineOf("lower"); }, "system/dpdDict", 0, "lower");
}

TEST(DictionaryErrors, UnknownKeyword) {
    const Dictionary d = Dictionary::parse("deltaT 0.1;\nendTime 1;\ndeltat 0.2;\n", "system/controlDict");
    const std::string msg = expectInputError([&] { d.checkKeys({"deltaT", "endTime", "writeInterval"}); },
                                             "system/controlDict", 3, "deltat");
    EXPECT_TRUE(contains(msg, "unknown keyword")) << msg;
    EXPECT_TRUE(contains(msg, "deltaT, endTime, writeInterval")) << msg;
    EXPECT_TRUE(contains(msg, "did you mean 'deltaT'")) << msg;
    EXPECT_NO_THROW(d.checkKeys({"deltaT", "endTime", "deltat"}));

    const Dictionary nested = Dictionary::parse("walls\n{\n    lower\n    {\n        speed 1;\n    }\n}\n", "w");
    expectInputError([&] { nested.subDict("walls").checkKeys({"upper"}); }, "w", 3, "lower");
}

TEST(DictionaryErrors, WrongType) {
    const Dictionary d = Dictionary::parse(R"(n 2.5;
x abc;
v (1 2);
s (a b);
w (1 abc 3);
sub { }
big 99999999999;
huge 1e999;
count 3(1 2);
)",
                                           "types");
    std::string msg = expectInputError([&] { d.get<int>("n"); }, "types", 1, "n");
    EXPECT_TRUE(contains(msg, "integer")) << msg;
    EXPECT_TRUE(contains(msg, "'2.5'")) << msg;
    msg = expectInputError([&] { d.get<double>("x"); }, "types", 2, "x");
    EXPECT_TRUE(contains(msg, "number")) << msg;
    msg = expectInputError([&] { d.get<Eigen::Vector3d>("v"); }, "types", 3, "v");
    EXPECT_TRUE(contains(msg, "3")) << msg;
    expectInputError([&] { d.get<std::string>("s"); }, "types", 4, "s");
    expectInputError([&] { d.get<std::vector<std::string>>("n"); }, "types", 1, "n");
    msg = expectInputError([&] { d.get<std::vector<double>>("w"); }, "types", 5, "w");
    EXPECT_TRUE(contains(msg, "'abc' is not a number")) << msg;
    expectInputError([&] { d.get<double>("sub"); }, "types", 6, "sub");
    expectInputError([&] { d.subDict("n"); }, "types", 1, "n");
    expectInputError([&] { d.get<int>("big"); }, "types", 7, "big");
    EXPECT_EQ(d.get<long long>("big"), 99999999999LL);
    expectInputError([&] { d.get<double>("huge"); }, "types", 8, "huge");
    msg = expectInputError([&] { d.get<std::vector<double>>("count"); }, "types", 9, "count");
    EXPECT_TRUE(contains(msg, "length")) << msg;
    // inf, nan and hex floats are not accepted as numbers.
    const Dictionary odd = Dictionary::parse("a inf;\nb nan;\nc 0x10;\nd 1e;\ne .5;\n", "odd");
    expectInputError([&] { odd.get<double>("a"); }, "odd", 1, "a");
    expectInputError([&] { odd.get<double>("b"); }, "odd", 2, "b");
    expectInputError([&] { odd.get<double>("c"); }, "odd", 3, "c");
    expectInputError([&] { odd.get<double>("d"); }, "odd", 4, "d");
    EXPECT_DOUBLE_EQ(odd.get<double>("e"), 0.5);
}

TEST(DictionaryErrors, WrongTypeInMultiLineListNamesTheElementLine) {
    const Dictionary d = Dictionary::parse("points\n(\n    (0 0 0)\n    (1 x 0)\n);\n", "pts");
    expectInputError([&] { d.get<std::vector<Eigen::Vector3d>>("points"); }, "pts", 4, "points");
}

TEST(DictionaryErrors, UnclosedBraceNamesWhereItOpened) {
    const std::string text = "a 1;\nwalls\n{\n    lower\n    {\n        x 1;\n    }\n\nb 2;\n";
    const std::string msg = expectInputError([&] { Dictionary::parse(text, "unclosed"); }, "unclosed", 3, "walls");
    EXPECT_TRUE(contains(msg, "unclosed '{'")) << msg;
}

TEST(DictionaryErrors, StrayClosingBrace) {
    const std::string msg =
        expectInputError([] { Dictionary::parse("a 1;\nsub { b 2; }\n}\nc 3;\n", "stray"); }, "stray", 3, "");
    EXPECT_TRUE(contains(msg, "'}'")) << msg;
}

TEST(DictionaryErrors, UnbalancedParentheses) {
    std::string msg = expectInputError(
        [] { Dictionary::parse("a 1;\npoints\n(\n    (0 0 0\n    (1 0 0)\n);\n", "parens"); }, "parens", 3, "points");
    EXPECT_TRUE(contains(msg, "unclosed '('")) << msg;
    expectInputError([] { Dictionary::parse("a 1;\nv (1 2));\n", "parens"); }, "parens", 2, "v");
    expectInputError([] { Dictionary::parse("v (1 2\n", "parens"); }, "parens", 1, "v");
    expectInputError([] { Dictionary::parse("a 1;\n)\n", "parens"); }, "parens", 2, "");
}

TEST(DictionaryErrors, MissingSemicolon) {
    // The next line starts a new entry.
    std::string msg =
        expectInputError([] { Dictionary::parse("a 1;\ndeltaT 0.01\nendTime 10;\n", "semi"); }, "semi", 2, "deltaT");
    EXPECT_TRUE(contains(msg, "missing ';'")) << msg;
    // The value runs into the end of its dictionary, a sub-dictionary or the file.
    expectInputError([] { Dictionary::parse("sub\n{\n    x 1\n}\n", "semi"); }, "semi", 3, "x");
    expectInputError([] { Dictionary::parse("a 1;\nb 2", "semi"); }, "semi", 2, "b");
    expectInputError([] { Dictionary::parse("a 1 sub { }\n", "semi"); }, "semi", 1, "a");
    expectInputError([] { Dictionary::parse("x 1;\ns { $x }\n", "semi"); }, "semi", 2, "$x");
}

TEST(DictionaryErrors, UnterminatedStringAndComment) {
    std::string msg =
        expectInputError([] { Dictionary::parse("a 1;\nname \"abc;\nb 2;\n", "str"); }, "str", 2, "");
    EXPECT_TRUE(contains(msg, "unterminated string")) << msg;
    msg = expectInputError([] { Dictionary::parse("a 1;\n/* open\ncomment\nb 2;\n", "cmt"); }, "cmt", 2, "");
    EXPECT_TRUE(contains(msg, "unterminated comment")) << msg;
}

TEST(DictionaryErrors, OtherSyntaxErrors) {
    expectInputError([] { Dictionary::parse("a 1;\n#includeEtc \"x\"\n", "dir"); }, "dir", 2, "#includeEtc");
    expectInputError([] { Dictionary::parse("a 1;\n(1 2);\n", "kw"); }, "kw", 2, "");
    expectInputError([] { Dictionary::parse("a 1;\n{ b 1; }\n", "kw"); }, "kw", 2, "");
}

TEST(DictionaryErrors, PositiveAndNonNegative) {
    const Dictionary d = Dictionary::parse("a 2;\nsub\n{\n    rho -3;\n    zero 0;\n    n -1;\n}\n", "constant/dpd");
    EXPECT_EQ(d.getPositive<int>("a"), 2);
    const Dictionary& sub = d.subDict("sub");
    std::string msg = expectInputError([&] { sub.getPositive<double>("rho"); }, "constant/dpd", 4, "rho");
    EXPECT_TRUE(contains(msg, "must be positive")) << msg;
    EXPECT_TRUE(contains(msg, "-3")) << msg;
    EXPECT_TRUE(contains(msg, "sub")) << msg;
    expectInputError([&] { sub.getPositive<double>("zero"); }, "constant/dpd", 5, "zero");
    EXPECT_EQ(sub.getNonNegative<double>("zero"), 0.0);
    msg = expectInputError([&] { sub.getNonNegative<long>("n"); }, "constant/dpd", 6, "n");
    EXPECT_TRUE(contains(msg, "must be non-negative")) << msg;
}

TEST(DictionaryErrors, FailNamesKeyLineOrDictionaryLine) {
    const Dictionary d = Dictionary::parse("a 1;\nwalls\n{\n    speed 5;\n}\n", "f");
    std::string msg = expectInputError([&] { d.subDict("walls").fail("speed", "must be below 1"); }, "f", 4, "speed");
    EXPECT_TRUE(contains(msg, "must be below 1")) << msg;
    expectInputError([&] { d.subDict("walls").fail("absent", "is needed"); }, "f", 2, "absent");
}

// ---- editing and writing -----------------------------------------------------------------------

TEST(DictionaryWrite, SetAndFormat) {
    Dictionary d("system/controlDict");
    d.set("deltaT", "0.01");
    d.set("value", "(1 0 0)");
    d.setValue("name", std::string("a b"));
    d.setValue("word", "GrootWarren");
    d.setValue("on", true);
    Dictionary& lower = d.subDictOrCreate("walls").subDictOrCreate("lower");
    lower.setValue("velocity", Eigen::Vector3d(1, 0, 0));
    EXPECT_EQ(lower.path(), "walls/lower");
    EXPECT_EQ(&d.subDictOrCreate("walls").subDictOrCreate("lower"), &lower);
    d.set("after", "((0 0) (1 1))");
    d.set("deltaT", "0.02");  // replaces in place
    EXPECT_EQ(d.toString(), "deltaT          0.02;\n"
                            "value           (1 0 0);\n"
                            "name            \"a b\";\n"
                            "word            GrootWarren;\n"
                            "on              true;\n"
                            "\n"
                            "walls\n"
                            "{\n"
                            "    lower\n"
                            "    {\n"
                            "        velocity        (1 0 0);\n"
                            "    }\n"
                            "}\n"
                            "\n"
                            "after           ((0 0) (1 1));\n");
    EXPECT_TRUE(d.remove("after"));
    EXPECT_FALSE(d.remove("after"));
    EXPECT_FALSE(d.found("after"));
    expectInputError([&] { d.set("bad", "(1 2"); }, "system/controlDict", 0, "bad");
    expectInputError([&] { d.set("bad", "1; x 2"); }, "system/controlDict", 0, "bad");
    expectInputError([&] { d.subDictOrCreate("deltaT"); }, "system/controlDict", 0, "deltaT");
}

TEST(DictionaryWrite, ToStringRoundTrip) {
    Dictionary d = Dictionary::parse(kControlDict, "system/controlDict");
    d.setValue("third", 1.0 / 3.0);
    d.setValue("tiny", 1e-300);
    d.setValue("list", std::vector<double>{0.1, -2.5e-7, 3});
    d.setValue("names", std::vector<std::string>{"fluid", "frozen wall", "q\"uote"});
    d.setValue("ints", std::vector<int>{1, -2});
    d.setValue("big", 12345678901LL);
    d.setValue("odd key", 1);
    d.subDictOrCreate("walls").set("segments", "((0 0) (1 1))");

    const Dictionary back = Dictionary::parse(d.toString(), "copy");
    EXPECT_EQ(back.keys(), d.keys());
    EXPECT_EQ(back.get<double>("deltaT"), d.get<double>("deltaT"));
    EXPECT_EQ(back.get<double>("tolerance"), -1e-3);
    EXPECT_EQ(back.get<std::string>("title"), "a b");
    EXPECT_EQ(back.get<double>("third"), 1.0 / 3.0);
    EXPECT_EQ(back.get<double>("tiny"), 1e-300);
    EXPECT_EQ(back.get<std::vector<double>>("list"), (std::vector<double>{0.1, -2.5e-7, 3}));
    EXPECT_EQ(back.get<std::vector<std::string>>("names"),
              (std::vector<std::string>{"fluid", "frozen wall", "q\"uote"}));
    EXPECT_EQ(back.get<std::vector<int>>("ints"), (std::vector<int>{1, -2}));
    EXPECT_EQ(back.get<long long>("big"), 12345678901LL);
    EXPECT_EQ(back.get<int>("odd key"), 1);
    EXPECT_EQ(back.subDict("walls").get<std::vector<std::vector<double>>>("segments"),
              (std::vector<std::vector<double>>{{0, 0}, {1, 1}}));
    EXPECT_EQ(back.toString(), d.toString());
}

TEST_F(DictionaryFiles, WriteDictionaryFileRoundTrip) {
    Dictionary d = Dictionary::parse(kControlDict, "source");
    d.subDictOrCreate("walls").subDictOrCreate("lower").setValue("velocity", Eigen::Vector3d(0.5, 0, -1));
    const std::string path = pathOf("controlDict");
    write("controlDict", "old content that must be replaced {");
    dpd::writeDictionaryFile(path, d);

    const Dictionary back = Dictionary::readFile(path);
    EXPECT_EQ(back.subDict("FoamFile").get<std::string>("object"), "controlDict");
    EXPECT_EQ(back.subDict("FoamFile").get<std::string>("class"), "dictionary");
    EXPECT_EQ(back.keys(), d.keys());
    for (const std::string& key : d.keys()) {
        if (!d.isDict(key)) {
            EXPECT_EQ(back.rawValue(key), d.rawValue(key)) << key;
        }
    }
    EXPECT_EQ(back.subDict("walls").subDict("lower").get<Eigen::Vector3d>("velocity"),
              Eigen::Vector3d(0.5, 0, -1));
    // Only the file itself is left: the temporary was renamed onto it.
    int files = 0;
    for (const auto& entry : fs::directory_iterator(dir_)) {
        ++files;
        EXPECT_EQ(entry.path().filename(), "controlDict");
    }
    EXPECT_EQ(files, 1);
}

TEST_F(DictionaryFiles, WriteIntoMissingDirectoryIsAnIoError) {
    EXPECT_THROW(dpd::writeDictionaryFile(pathOf("no/such/dir/controlDict"), Dictionary()), dpd::IoError);
}
