#include "io/DictionaryDetail.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

namespace dpd {
namespace detail {

namespace {

std::size_t editDistance(const std::string& a, const std::string& b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t above = row[j];
            const std::size_t change = diagonal + (a[i - 1] == b[j - 1] ? 0 : 1);
            row[j] = std::min({above + 1, row[j - 1] + 1, change});
            diagonal = above;
        }
    }
    return row[b.size()];
}

}  // namespace

std::string joinPath(const std::string& scope, const std::string& key) {
    return scope.empty() ? key : scope + "/" + key;
}

std::string joinWords(const std::vector<std::string>& words, const std::string& sep) {
    std::string out;
    for (std::size_t i = 0; i < words.size(); ++i) out += (i ? sep : "") + words[i];
    return out;
}

std::string joinTokens(const std::vector<DictToken>& tokens) {
    std::string out;
    for (std::size_t i = 0; i < tokens.size(); ++i) {
        const bool tight = i == 0 || tokens[i - 1].isPunct('(') || tokens[i].isPunct(')');
        if (!tight) out += ' ';
        out += tokenText(tokens[i]);
    }
    return out;
}

bool readText(const std::string& path, std::string& text) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) return false;
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    std::ostringstream buffer;
    buffer << in.rdbuf();
    text = buffer.str();
    return !in.bad();
}

std::string suggestion(const std::string& key, const std::vector<std::string>& allowed) {
    std::string best;
    std::size_t bestDistance = 3;  // typos of up to two characters
    for (const std::string& a : allowed) {
        const std::size_t d = editDistance(key, a);
        if (d < bestDistance) {
            bestDistance = d;
            best = a;
        }
    }
    return best.empty() ? "" : " (did you mean '" + best + "'?)";
}

std::string formatWord(const std::string& s) { return isPlainWord(s) ? s : quoteString(s); }

}  // namespace detail
}  // namespace dpd
