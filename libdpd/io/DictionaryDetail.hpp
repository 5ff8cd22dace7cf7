#pragma once
// What the parts of io/Dictionary share and users never see: an entry, a value being converted, and
// small text helpers.
#include "io/Dictionary.hpp"
#include "io/DictionaryLexer.hpp"

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace dpd {
namespace detail {

struct DictEntry {
    std::string key;
    std::string file;  // differs from the dictionary's own file for entries of an #include'd file
    int line = 0;      // 0 for entries made by set()
    std::vector<DictToken> value;
    std::unique_ptr<Dictionary> dict;  // set for sub-dictionaries, which have no value tokens

    DictEntry() = default;
    DictEntry(std::string k, std::string f, int l) : key(std::move(k)), file(std::move(f)), line(l) {}
    DictEntry(const DictEntry& o)
        : key(o.key), file(o.file), line(o.line), value(o.value),
          dict(o.dict ? std::make_unique<Dictionary>(*o.dict) : nullptr) {}
    DictEntry(DictEntry&&) noexcept = default;
    DictEntry& operator=(const DictEntry& o) {
        if (this != &o) *this = DictEntry(o);
        return *this;
    }
    DictEntry& operator=(DictEntry&&) noexcept = default;
};

// What a typed getter needs to convert a value and to word an error about it.
struct DictValue {
    const std::string& file;
    int line;
    const std::string& key;
    const std::vector<DictToken>& tokens;
    std::string expected;  // e.g. "a number"
    std::string note;      // scope note, e.g. " (in walls/lower)"
};


inline constexpr int kMaxIncludeDepth = 32;
// Sub-dictionaries and lists nested deeper than this are refused (no case needs more; the readers
// recurse, and garbage must not exhaust the stack).
inline constexpr int kMaxNesting = 64;
inline constexpr std::size_t kKeywordColumn = 16;  // OpenFOAM pads keywords to this width

std::string joinPath(const std::string& scope, const std::string& key);
std::string joinWords(const std::vector<std::string>& words, const std::string& sep);
// Tokens as one line of text: "(0.02 0 0)", "((0 0) (1 1))", "GrootWarren".
std::string joinTokens(const std::vector<DictToken>& tokens);
// A file's whole text; false when it cannot be read.
bool readText(const std::string& path, std::string& text);
// A word as a dictionary writes it: plain, or quoted when it is not a plain word.
std::string formatWord(const std::string& s);
// " (did you mean 'deltaT'?)" for a near miss of an allowed keyword, else "".
std::string suggestion(const std::string& key, const std::vector<std::string>& allowed);

}  // namespace detail
}  // namespace dpd
