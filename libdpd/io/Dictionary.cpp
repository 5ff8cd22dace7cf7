#include "io/Dictionary.hpp"

#include "core/Axis.hpp"
#include "io/AtomicFile.hpp"

#include "core/Error.hpp"
#include "io/DictionaryLexer.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <system_error>

#include <unistd.h>

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

}  // namespace detail

using detail::DictEntry;
using detail::DictValue;

namespace {

constexpr int kMaxIncludeDepth = 32;
constexpr std::size_t kKeywordColumn = 16;  // OpenFOAM pads keywords to this width

std::string joinPath(const std::string& scope, const std::string& key) {
    return scope.empty() ? key : scope + "/" + key;
}

std::string joinWords(const std::vector<std::string>& words, const std::string& sep) {
    std::string out;
    for (std::size_t i = 0; i < words.size(); ++i) out += (i ? sep : "") + words[i];
    return out;
}

// Tokens as one line of text: "(0.02 0 0)", "((0 0) (1 1))", "GrootWarren".
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

// " (did you mean 'deltaT'?)" for a near miss of an allowed keyword, else "".
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

// ---- typed values ------------------------------------------------------------------------------

// A value as a tree: an atom (one word or string) or a list of nodes.
struct Node {
    const DictToken* atom = nullptr;  // null for a list
    std::vector<Node> items;
    int line = 0;
    bool isList() const { return atom == nullptr; }
};

[[noreturn]] void badValue(const DictValue& v, int line, const std::string& why = "") {
    std::string msg = "expected " + v.expected + " but found ";
    msg += v.tokens.empty() ? std::string("no value") : "'" + joinTokens(v.tokens) + "'";
    if (!why.empty()) msg += " (" + why + ")";
    throw InputError(v.file, line, v.key, msg + v.note);
}

std::string describe(const Node& n) { return n.isList() ? "a list" : "'" + tokenText(*n.atom) + "'"; }

bool isDigits(const std::string& s, std::size_t from) {
    if (from >= s.size()) return false;
    for (std::size_t i = from; i < s.size(); ++i)
        if (!std::isdigit(static_cast<unsigned char>(s[i]))) return false;
    return true;
}

bool looksLikeInteger(const std::string& s) {
    return isDigits(s, !s.empty() && (s[0] == '+' || s[0] == '-') ? 1 : 0);
}

// Plain decimal notation only: strtod alone would also take "inf", "nan" and hex floats.
bool looksLikeNumber(const std::string& s) {
    const auto digitsFrom = [&s](std::size_t& i) {
        std::size_t n = 0;
        for (; i < s.size() && std::isdigit(static_cast<unsigned char>(s[i])); ++i) ++n;
        return n;
    };
    std::size_t i = 0;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    std::size_t mantissaDigits = digitsFrom(i);
    if (i < s.size() && s[i] == '.') mantissaDigits += digitsFrom(++i);
    if (mantissaDigits == 0) return false;
    if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
        ++i;
        if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
        if (digitsFrom(i) == 0) return false;
    }
    return i == s.size();
}

// An OpenFOAM list may be written with its length in front, 3(1 2 3); the length must match.
bool isLengthPrefix(const Node& n) {
    return !n.isList() && n.atom->kind == DictToken::Kind::Word && isDigits(n.atom->text, 0);
}

std::vector<Node> readItems(const DictValue& v, std::size_t& pos) {
    std::vector<Node> items;
    while (pos < v.tokens.size() && !v.tokens[pos].isPunct(')')) {
        const DictToken& t = v.tokens[pos++];
        Node node;
        node.line = t.line;
        if (t.isPunct('(')) {
            node.items = readItems(v, pos);
            ++pos;  // the ')': the parser only stores balanced parentheses
        } else {
            node.atom = &t;
        }
        if (node.isList() && !items.empty() && isLengthPrefix(items.back())) {
            const std::string& length = items.back().atom->text;
            if (length != std::to_string(node.items.size()))
                badValue(v, items.back().line, "the length prefix says " + length + " but the list has " +
                                                   std::to_string(node.items.size()) + " elements");
            items.back() = std::move(node);
        } else {
            items.push_back(std::move(node));
        }
    }
    return items;
}

Node singleNode(const DictValue& v) {
    std::size_t pos = 0;
    std::vector<Node> nodes = readItems(v, pos);
    if (nodes.size() != 1) badValue(v, v.line);
    return std::move(nodes[0]);
}

Node listNode(const DictValue& v) {
    Node n = singleNode(v);
    if (!n.isList()) badValue(v, n.line);
    return n;
}

// For a value of several tokens, say which element is wrong; for a single token it is obvious.
std::string elementWhy(const DictValue& v, const Node& n, const std::string& what) {
    return v.tokens.size() > 1 ? describe(n) + " is not " + what : "";
}

double toDouble(const DictValue& v, const Node& n) {
    if (n.isList() || n.atom->kind != DictToken::Kind::Word || !looksLikeNumber(n.atom->text))
        badValue(v, n.line, elementWhy(v, n, "a number"));
    errno = 0;
    const double x = std::strtod(n.atom->text.c_str(), nullptr);
    if (errno == ERANGE && std::abs(x) > 1.0) badValue(v, n.line, describe(n) + " is out of range");
    return x;
}

long long toInteger(const DictValue& v, const Node& n, long long lo, long long hi) {
    if (n.isList() || n.atom->kind != DictToken::Kind::Word || !looksLikeInteger(n.atom->text))
        badValue(v, n.line, elementWhy(v, n, "an integer"));
    errno = 0;
    const long long x = std::strtoll(n.atom->text.c_str(), nullptr, 10);
    if (errno == ERANGE || x < lo || x > hi) badValue(v, n.line, describe(n) + " is out of range");
    return x;
}

std::string toText(const DictValue& v, const Node& n) {
    if (n.isList()) badValue(v, n.line, elementWhy(v, n, "a word"));
    return n.atom->text;
}

Eigen::Vector3d toVector3(const DictValue& v, const Node& n) {
    if (!n.isList()) badValue(v, n.line, elementWhy(v, n, "a list of 3 numbers"));
    if (n.items.size() != 3)
        badValue(v, n.line, "a vector needs 3 elements, not " + std::to_string(n.items.size()));
    return {toDouble(v, n.items[0]), toDouble(v, n.items[1]), toDouble(v, n.items[2])};
}

template <class T, class Convert>
std::vector<T> toList(const DictValue& v, Convert convert) {
    const Node list = listNode(v);
    std::vector<T> out;
    out.reserve(list.items.size());
    for (const Node& n : list.items) out.push_back(convert(v, n));
    return out;
}

std::string formatDouble(double x) {
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, x);  // shortest exact form
    return std::string(buffer, result.ptr);
}

template <class Sequence, class Format>
std::string formatList(const Sequence& items, Format format) {
    std::string out = "(";
    for (std::size_t i = 0; i < static_cast<std::size_t>(items.size()); ++i)
        out += (i ? " " : "") + format(items[i]);
    return out + ")";
}

std::string formatWord(const std::string& s) { return isPlainWord(s) ? s : quoteString(s); }

}  // namespace

// ---- parser ------------------------------------------------------------------------------------

// Reads tokens into Dictionary entries. Macros and #include are resolved while reading, as in
// OpenFOAM, so a macro sees the entries above it in this and the enclosing dictionaries (scopes_).
class DictionaryParser {
public:
    explicit DictionaryParser(Dictionary& root) { scopes_.push_back(&root); }

    // Reads one file's text into dict. Included files are read with dropHeader: their FoamFile
    // header describes that file, not the dictionary it is included into.
    void parseFile(const std::string& text, const std::string& file, Dictionary& dict, bool dropHeader) {
        Cursor c{tokenizeDictionary(text, file), 0, file};
        parseBody(c, dict, nullptr, "", dropHeader);
    }

private:
    struct Cursor {
        std::vector<DictToken> tokens;  // never empty: ends with an End token
        std::size_t pos = 0;
        std::string file;
        const DictToken& peek(std::size_t ahead = 0) const {
            return tokens[std::min(pos + ahead, tokens.size() - 1)];
        }
        const DictToken& next() {
            const DictToken& t = peek();
            if (pos + 1 < tokens.size()) ++pos;
            return t;
        }
    };

    // Entries up to the '}' matching openBrace, or up to the end of the file when openBrace is null.
    void parseBody(Cursor& c, Dictionary& dict, const DictToken* openBrace, const std::string& name,
                   bool dropHeader) {
        for (;;) {
            const DictToken& t = c.next();
            if (t.kind == DictToken::Kind::End) {
                if (openBrace)
                    throw InputError(c.file, openBrace->line, name,
                                     "unclosed '{': no matching '}' before the end of the file");
                return;
            }
            if (t.isPunct('}')) {
                if (openBrace) return;
                throw InputError(c.file, t.line, "", "unexpected '}' with no matching '{'");
            }
            if (t.isPunct(';')) continue;  // "};" after a sub-dictionary is common OpenFOAM style
            if (t.isPunct(')')) throw InputError(c.file, t.line, "", "unexpected ')' with no matching '('");
            if (t.kind == DictToken::Kind::Punct)
                throw InputError(c.file, t.line, "", "expected a keyword but found '" + t.text + "'");
            if (t.kind == DictToken::Kind::Directive) parseDirective(c, dict, t);
            else if (t.kind == DictToken::Kind::Macro) parseMacroEntry(c, dict, t);
            else parseEntry(c, dict, t, dropHeader);
        }
    }

    void parseEntry(Cursor& c, Dictionary& dict, const DictToken& keyTok, bool dropHeader) {
        if (c.peek().isPunct('{')) return parseSubDict(c, dict, keyTok, dropHeader);
        if (c.peek().kind == DictToken::Kind::Macro && c.peek(1).isPunct(';')) {
            const DictEntry& target = resolveMacro(c, c.peek(), keyTok.text);
            if (target.dict) return copySubDict(c, dict, keyTok, *target.dict);
        }
        DictEntry entry(keyTok.text, c.file, keyTok.line);
        entry.value = readValue(c, keyTok);
        dict.insert(std::move(entry));
    }

    void parseSubDict(Cursor& c, Dictionary& dict, const DictToken& keyTok, bool dropHeader) {
        const DictToken& brace = c.next();
        auto child = std::make_unique<Dictionary>(c.file);
        child->line_ = keyTok.line;
        child->path_ = joinPath(dict.path_, keyTok.text);
        scopes_.push_back(child.get());
        parseBody(c, *child, &brace, keyTok.text, false);
        scopes_.pop_back();
        if (dropHeader && keyTok.text == "FoamFile") return;
        DictEntry entry(keyTok.text, c.file, keyTok.line);
        entry.dict = std::move(child);
        dict.insert(std::move(entry));
    }

    // "key $otherDict;" makes key a copy of that sub-dictionary.
    void copySubDict(Cursor& c, Dictionary& dict, const DictToken& keyTok, const Dictionary& source) {
        c.next();  // the macro
        c.next();  // ';'
        DictEntry entry(keyTok.text, c.file, keyTok.line);
        entry.dict = std::make_unique<Dictionary>(source);
        entry.dict->file_ = c.file;
        entry.dict->line_ = keyTok.line;
        entry.dict->rescope(joinPath(dict.path_, keyTok.text));
        dict.insert(std::move(entry));
    }

    // The tokens of a value up to its ';'. A missing ';' is caught when the value runs into '}', '{'
    // or the end of the file, or when a new line starts outside parentheses: values span lines only
    // inside lists, so "deltaT 0.01 <newline> endTime 10;" is a forgotten ';' after 0.01.
    std::vector<DictToken> readValue(Cursor& c, const DictToken& keyTok) {
        const std::string& key = keyTok.text;
        std::vector<DictToken> value;
        std::vector<int> openParens;  // lines of the '(' not closed yet
        int lastLine = keyTok.line;
        for (;;) {
            const DictToken& t = c.peek();
            if (endsValue(t)) {
                if (!openParens.empty())
                    throw InputError(c.file, openParens.back(), key,
                                     "unclosed '(': no matching ')' before " + describeEnd(t));
                if (t.isPunct(';')) {
                    c.next();
                    return value;
                }
                throw InputError(c.file, lastLine, key, "missing ';' at the end of the entry");
            }
            c.next();
            if (t.isPunct('(')) {
                openParens.push_back(t.line);
            } else if (t.isPunct(')')) {
                if (openParens.empty())
                    throw InputError(c.file, t.line, key, "unexpected ')' with no matching '('");
                openParens.pop_back();
            } else if (t.kind == DictToken::Kind::Directive) {
                throw InputError(c.file, t.line, key, t.text + " cannot appear inside a value");
            } else if (openParens.empty() && !value.empty() && t.line > lastLine) {
                throw InputError(c.file, lastLine, key,
                                 "missing ';' at the end of the entry (a value continues onto the next "
                                 "line only inside parentheses)");
            }
            if (t.kind == DictToken::Kind::Macro) expandMacro(c, t, key, value);
            else value.push_back(t);
            lastLine = t.line;
        }
    }

    static bool endsValue(const DictToken& t) {
        return t.kind == DictToken::Kind::End || t.isPunct(';') || t.isPunct('{') || t.isPunct('}');
    }
    static std::string describeEnd(const DictToken& t) {
        return t.kind == DictToken::Kind::End ? "the end of the file" : "'" + t.text + "'";
    }

    void expandMacro(const Cursor& c, const DictToken& macro, const std::string& key,
                     std::vector<DictToken>& value) {
        const DictEntry& target = resolveMacro(c, macro, key);
        if (target.dict)
            throw InputError(c.file, macro.line, key,
                             "$" + macro.text + " names a sub-dictionary; use it alone, as in 'key $" +
                                 macro.text + ";'");
        for (DictToken t : target.value) {
            t.line = macro.line;  // errors about the value point at the use of the macro
            value.push_back(std::move(t));
        }
    }

    // "$defaults;" inside a dictionary merges the entries of the sub-dictionary defaults into it.
    void parseMacroEntry(Cursor& c, Dictionary& dict, const DictToken& macro) {
        const std::string keyword = "$" + macro.text;
        const DictEntry& target = resolveMacro(c, macro, keyword);
        if (!target.dict)
            throw InputError(c.file, macro.line, keyword,
                             "a macro standing as an entry must name a sub-dictionary");
        if (!c.peek().isPunct(';')) throw InputError(c.file, macro.line, keyword, "missing ';' after the macro");
        c.next();
        const Dictionary source = *target.dict;  // a copy: merging may move the entry it lives in
        dict.mergeFrom(source);
    }

    // $name: the innermost scope that has it wins; $a.b.c walks into sub-dictionaries; $:a.b starts
    // at the top level.
    const DictEntry& resolveMacro(const Cursor& c, const DictToken& macro, const std::string& key) const {
        const std::string& name = macro.text;
        const DictEntry* found = nullptr;
        if (name[0] == ':') {
            found = lookup(*scopes_.front(), name.substr(1));
        } else {
            for (auto scope = scopes_.rbegin(); scope != scopes_.rend() && !found; ++scope)
                found = lookup(**scope, name);
        }
        if (!found)
            throw InputError(c.file, macro.line, key,
                             "unknown macro $" + name + ": no such keyword in this or an enclosing dictionary");
        return *found;
    }

    // A keyword may itself contain dots, so the whole name is tried before each split at a dot.
    static const DictEntry* lookup(const Dictionary& dict, const std::string& name) {
        if (const DictEntry* e = dict.findEntry(name)) return e;
        for (std::size_t dot = name.find('.'); dot != std::string::npos; dot = name.find('.', dot + 1)) {
            const DictEntry* head = dict.findEntry(name.substr(0, dot));
            if (!head || !head->dict) continue;
            if (const DictEntry* e = lookup(*head->dict, name.substr(dot + 1))) return e;
        }
        return nullptr;
    }

    void parseDirective(Cursor& c, Dictionary& dict, const DictToken& directive) {
        const bool optional = directive.text == "#includeIfPresent";
        if (directive.text != "#include" && !optional)
            throw InputError(c.file, directive.line, directive.text,
                             "unknown directive (supported: #include, #includeIfPresent)");
        const DictToken& name = c.next();
        if (name.kind != DictToken::Kind::String && name.kind != DictToken::Kind::Word)
            throw InputError(c.file, directive.line, directive.text, "expected a file name, e.g. #include \"file\"");
        includeFile(c, dict, directive, name.text, optional);
    }

    void includeFile(const Cursor& c, Dictionary& dict, const DictToken& directive, const std::string& name,
                     bool optional) {
        namespace fs = std::filesystem;
        fs::path path(name);
        if (path.is_relative()) path = fs::path(c.file).parent_path() / path;
        std::string text;
        if (!readText(path.string(), text)) {
            if (optional) return;
            throw InputError(c.file, directive.line, directive.text,
                             "cannot open included file '" + name + "' (looked for " + path.string() + ")");
        }
        if (includeDepth_ >= kMaxIncludeDepth)
            throw InputError(c.file, directive.line, directive.text,
                             "includes nested more than " + std::to_string(kMaxIncludeDepth) +
                                 " deep (does a file include itself?)");
        ++includeDepth_;
        parseFile(text, path.string(), dict, true);
        --includeDepth_;
    }

    std::vector<Dictionary*> scopes_;  // the dictionaries being read, innermost last
    int includeDepth_ = 0;
};

// ---- Dictionary --------------------------------------------------------------------------------

Dictionary::Dictionary() = default;
Dictionary::Dictionary(std::string fileName) : file_(std::move(fileName)) {}
Dictionary::Dictionary(const Dictionary&) = default;
Dictionary::Dictionary(Dictionary&&) noexcept = default;
Dictionary& Dictionary::operator=(const Dictionary&) = default;
Dictionary& Dictionary::operator=(Dictionary&&) noexcept = default;
Dictionary::~Dictionary() = default;

Dictionary Dictionary::readFile(const std::string& path) {
    std::string text;
    if (!readText(path, text)) throw InputError(path, 0, "", "cannot open file");
    return parse(text, path);
}

Dictionary Dictionary::parse(const std::string& text, const std::string& fileName) {
    Dictionary root(fileName);
    DictionaryParser(root).parseFile(text, fileName, root, false);
    return root;
}

const DictEntry* Dictionary::findEntry(const std::string& key) const {
    for (const DictEntry& e : entries_)
        if (e.key == key) return &e;
    return nullptr;
}

DictEntry* Dictionary::findEntry(const std::string& key) {
    for (DictEntry& e : entries_)
        if (e.key == key) return &e;
    return nullptr;
}

bool Dictionary::isHeader(const DictEntry& e) const { return path_.empty() && e.dict && e.key == "FoamFile"; }

std::string Dictionary::scopeNote() const { return path_.empty() ? "" : " (in " + path_ + ")"; }

void Dictionary::missing(const std::string& key, const std::string& expected) const {
    throw InputError(file_, line_, key, "missing keyword; expected " + expected + scopeNote());
}

bool Dictionary::found(const std::string& key) const { return findEntry(key) != nullptr; }

bool Dictionary::isDict(const std::string& key) const {
    const DictEntry* e = findEntry(key);
    return e && e->dict;
}

const Dictionary& Dictionary::subDict(const std::string& key) const {
    const DictEntry* e = findEntry(key);
    if (!e) missing(key, "a sub-dictionary { ... }");
    if (!e->dict)
        throw InputError(e->file, e->line, key,
                         "expected a sub-dictionary { ... } but found '" + joinTokens(e->value) + "'" + scopeNote());
    return *e->dict;
}

std::vector<std::string> Dictionary::keys() const {
    std::vector<std::string> out;
    for (const DictEntry& e : entries_)
        if (!isHeader(e)) out.push_back(e.key);
    return out;
}

int Dictionary::lineOf(const std::string& key) const {
    const DictEntry* e = findEntry(key);
    if (!e) missing(key, "a value");
    return e->line;
}

int Dictionary::getAxis(const std::string& key) const {
    const std::string s = get<std::string>(key);
    const int axis = axisFromLetter(s);
    if (axis < 0) fail(key, "expected x, y or z, not '" + s + "'");
    return axis;
}

std::pair<double, double> Dictionary::getIncreasingPair(const std::string& key, const std::string& lowName,
                                                        const std::string& highName) const {
    const std::vector<double> pair = get<std::vector<double>>(key);
    if (pair.size() != 2 || !(pair[1] > pair[0]))
        fail(key, "expected (" + lowName + " " + highName + ") with " + highName + " > " + lowName);
    return {pair[0], pair[1]};
}

std::string Dictionary::rawValue(const std::string& key) const {
    const DictEntry* e = findEntry(key);
    if (!e) missing(key, "a value");
    if (e->dict) throw InputError(e->file, e->line, key, "expected a value but found a sub-dictionary" + scopeNote());
    return joinTokens(e->value);
}

DictValue Dictionary::valueOf(const std::string& key, const std::string& expected) const {
    const DictEntry* e = findEntry(key);
    if (!e) missing(key, expected);
    if (e->dict)
        throw InputError(e->file, e->line, key, "expected " + expected + " but found a sub-dictionary" + scopeNote());
    return {e->file, e->line, e->key, e->value, expected, scopeNote()};
}

std::string Dictionary::getOrDefault(const std::string& key, const char* def) const {
    return getOrDefault<std::string>(key, std::string(def));
}

void Dictionary::checkKeys(const std::vector<std::string>& allowed) const {
    for (const DictEntry& e : entries_) {
        if (isHeader(e) || std::find(allowed.begin(), allowed.end(), e.key) != allowed.end()) continue;
        const std::string list = allowed.empty() ? "none" : joinWords(allowed, ", ");
        throw InputError(e.file, e.line, e.key,
                         "unknown keyword" + suggestion(e.key, allowed) + "; allowed keywords: " + list + scopeNote());
    }
}

void Dictionary::fail(const std::string& key, const std::string& message) const {
    const DictEntry* e = findEntry(key);
    throw InputError(e ? e->file : file_, e ? e->line : line_, key, message + scopeNote());
}

// A later entry replaces an earlier one in place; two sub-dictionaries merge (OpenFOAM's default).
void Dictionary::insert(DictEntry entry) {
    DictEntry* old = findEntry(entry.key);
    if (!old) {
        entries_.push_back(std::move(entry));
    } else if (old->dict && entry.dict) {
        old->dict->mergeFrom(*entry.dict);
    } else {
        *old = std::move(entry);
    }
}

void Dictionary::mergeFrom(const Dictionary& other) {
    for (const DictEntry& e : other.entries_) {
        DictEntry copy(e);
        if (copy.dict) copy.dict->rescope(joinPath(path_, copy.key));
        insert(std::move(copy));
    }
}

void Dictionary::rescope(const std::string& path) {
    path_ = path;
    for (DictEntry& e : entries_)
        if (e.dict) e.dict->rescope(joinPath(path_, e.key));
}

void Dictionary::set(const std::string& key, const std::string& valueTokens) {
    const auto invalid = [&](const std::string& why) {
        return InputError(file_, 0, key, "cannot set value '" + valueTokens + "': " + why);
    };
    std::vector<DictToken> tokens;
    try {
        tokens = tokenizeDictionary(valueTokens, file_);
    } catch (const InputError&) {
        throw invalid("unterminated string or comment");
    }
    tokens.pop_back();  // End
    int depth = 0;
    for (DictToken& t : tokens) {
        if (t.isPunct('(')) ++depth;
        if (t.isPunct(')') && --depth < 0) throw invalid("unbalanced ')'");
        if (t.isPunct('{') || t.isPunct('}') || t.isPunct(';')) throw invalid("'" + t.text + "' is not allowed");
        if (t.kind == DictToken::Kind::Directive || t.kind == DictToken::Kind::Macro)
            throw invalid("directives and macros are not allowed");
        t.line = 0;  // not from a file: errors about it name no line
    }
    if (depth != 0) throw invalid("unbalanced '('");
    DictEntry entry(key, file_, 0);
    entry.value = std::move(tokens);
    DictEntry* old = findEntry(key);
    if (old) *old = std::move(entry);
    else entries_.push_back(std::move(entry));
}

void Dictionary::setValue(const std::string& key, const char* value) { setValue<std::string>(key, value); }

Dictionary& Dictionary::subDictOrCreate(const std::string& key) {
    if (DictEntry* e = findEntry(key)) {
        if (!e->dict) fail(key, "is a value, not a sub-dictionary");
        return *e->dict;
    }
    DictEntry entry(key, file_, 0);
    entry.dict = std::make_unique<Dictionary>(file_);
    entry.dict->path_ = joinPath(path_, key);
    entries_.push_back(std::move(entry));
    return *entries_.back().dict;
}

bool Dictionary::remove(const std::string& key) {
    const auto it = std::find_if(entries_.begin(), entries_.end(), [&](const DictEntry& e) { return e.key == key; });
    if (it == entries_.end()) return false;
    entries_.erase(it);
    return true;
}

std::string Dictionary::toString(int indent) const {
    const std::string pad(4 * static_cast<std::size_t>(std::max(indent, 0)), ' ');
    std::string out;
    bool afterBlock = false;  // blank lines around sub-dictionaries, as OpenFOAM writes them
    for (const DictEntry& e : entries_) {
        if (isHeader(e)) continue;
        const std::string key = formatWord(e.key);
        if (e.dict) {
            if (!out.empty()) out += '\n';
            out += pad + key + '\n' + pad + "{\n" + e.dict->toString(indent + 1) + pad + "}\n";
            afterBlock = true;
            continue;
        }
        if (afterBlock) out += '\n';
        afterBlock = false;
        out += pad + key;
        if (!e.value.empty()) out += std::string(kKeywordColumn - std::min(key.size(), kKeywordColumn - 1), ' ');
        out += joinTokens(e.value) + ";\n";
    }
    return out;
}

// ---- typed getters and setters -----------------------------------------------------------------

template <>
double Dictionary::get<double>(const std::string& key) const {
    const DictValue v = valueOf(key, "a number");
    return toDouble(v, singleNode(v));
}

template <>
int Dictionary::get<int>(const std::string& key) const {
    const DictValue v = valueOf(key, "an integer");
    return static_cast<int>(toInteger(v, singleNode(v), INT_MIN, INT_MAX));
}

template <>
long Dictionary::get<long>(const std::string& key) const {
    const DictValue v = valueOf(key, "an integer");
    return static_cast<long>(toInteger(v, singleNode(v), LONG_MIN, LONG_MAX));
}

template <>
long long Dictionary::get<long long>(const std::string& key) const {
    const DictValue v = valueOf(key, "an integer");
    return toInteger(v, singleNode(v), LLONG_MIN, LLONG_MAX);
}

template <>
bool Dictionary::get<bool>(const std::string& key) const {
    const DictValue v = valueOf(key, "a switch (yes/no, on/off, true/false)");
    const Node n = singleNode(v);
    if (!n.isList() && n.atom->kind == DictToken::Kind::Word) {
        const std::string& w = n.atom->text;
        if (w == "yes" || w == "on" || w == "true") return true;
        if (w == "no" || w == "off" || w == "false") return false;
    }
    badValue(v, n.line);
}

template <>
std::string Dictionary::get<std::string>(const std::string& key) const {
    const DictValue v = valueOf(key, "a word or quoted string");
    return toText(v, singleNode(v));
}

template <>
std::vector<double> Dictionary::get<std::vector<double>>(const std::string& key) const {
    return toList<double>(valueOf(key, "a list of numbers, e.g. (0 1.5 2)"), toDouble);
}

template <>
std::vector<int> Dictionary::get<std::vector<int>>(const std::string& key) const {
    const auto toInt = [](const DictValue& v, const Node& n) {
        return static_cast<int>(toInteger(v, n, INT_MIN, INT_MAX));
    };
    return toList<int>(valueOf(key, "a list of integers, e.g. (0 1 2)"), toInt);
}

template <>
std::vector<std::string> Dictionary::get<std::vector<std::string>>(const std::string& key) const {
    return toList<std::string>(valueOf(key, "a list of words, e.g. (fluid wall)"), toText);
}

template <>
Eigen::Vector3d Dictionary::get<Eigen::Vector3d>(const std::string& key) const {
    const DictValue v = valueOf(key, "a vector of 3 numbers, e.g. (1 0 0)");
    return toVector3(v, singleNode(v));
}

template <>
std::vector<Eigen::Vector3d> Dictionary::get<std::vector<Eigen::Vector3d>>(const std::string& key) const {
    return toList<Eigen::Vector3d>(valueOf(key, "a list of vectors, e.g. ((0 0 0) (1 0 0))"), toVector3);
}

template <>
std::vector<std::vector<double>> Dictionary::get<std::vector<std::vector<double>>>(const std::string& key) const {
    const auto toNumbers = [](const DictValue& v, const Node& n) {
        if (!n.isList()) badValue(v, n.line, elementWhy(v, n, "a list"));
        std::vector<double> out;
        for (const Node& item : n.items) out.push_back(toDouble(v, item));
        return out;
    };
    return toList<std::vector<double>>(valueOf(key, "a list of lists of numbers, e.g. ((0 0) (1 1))"), toNumbers);
}

template <>
void Dictionary::setValue<double>(const std::string& key, const double& value) {
    if (!std::isfinite(value)) throw InputError(file_, 0, key, "cannot store a value that is not finite");
    set(key, formatDouble(value));
}

template <>
void Dictionary::setValue<int>(const std::string& key, const int& value) { set(key, std::to_string(value)); }

template <>
void Dictionary::setValue<long>(const std::string& key, const long& value) { set(key, std::to_string(value)); }

template <>
void Dictionary::setValue<long long>(const std::string& key, const long long& value) {
    set(key, std::to_string(value));
}

template <>
void Dictionary::setValue<bool>(const std::string& key, const bool& value) { set(key, value ? "true" : "false"); }

template <>
void Dictionary::setValue<std::string>(const std::string& key, const std::string& value) {
    if (value.find('\n') != std::string::npos)
        throw InputError(file_, 0, key, "a string value cannot contain a line break");
    set(key, formatWord(value));
}

template <>
void Dictionary::setValue<std::vector<double>>(const std::string& key, const std::vector<double>& value) {
    for (double x : value)
        if (!std::isfinite(x)) throw InputError(file_, 0, key, "cannot store a value that is not finite");
    set(key, formatList(value, formatDouble));
}

template <>
void Dictionary::setValue<std::vector<int>>(const std::string& key, const std::vector<int>& value) {
    set(key, formatList(value, [](int i) { return std::to_string(i); }));
}

template <>
void Dictionary::setValue<std::vector<std::string>>(const std::string& key, const std::vector<std::string>& value) {
    for (const std::string& s : value)
        if (s.find('\n') != std::string::npos)
            throw InputError(file_, 0, key, "a string value cannot contain a line break");
    set(key, formatList(value, formatWord));
}

template <>
void Dictionary::setValue<Eigen::Vector3d>(const std::string& key, const Eigen::Vector3d& value) {
    setValue(key, std::vector<double>{value.x(), value.y(), value.z()});
}

// ---- files -------------------------------------------------------------------------------------

namespace {

std::string fileHeader(const Dictionary& dict, const std::string& object) {
    std::string cls = "dictionary";
    if (dict.isDict("FoamFile")) cls = dict.subDict("FoamFile").getOrDefault<std::string>("class", cls);
    return "/*--------------------------------*- C++ -*----------------------------------*\\\n"
           "  Written by the dpd toolkit\n"
           "\\*---------------------------------------------------------------------------*/\n"
           "FoamFile\n{\n"
           "    version     2.0;\n"
           "    format      ascii;\n"
           "    class       " + formatWord(cls) + ";\n"
           "    object      " + formatWord(object) + ";\n"
           "}\n"
           "// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //\n\n";
}

const char* const kFileFooter = "\n// ************************************************************************* //\n";

}  // namespace

void writeDictionaryFile(const std::string& path, const Dictionary& dict) {
    namespace fs = std::filesystem;
    const std::string text = fileHeader(dict, fs::path(path).filename().string()) + dict.toString() + kFileFooter;
    writeTextFileAtomically(path, text);
}

}  // namespace dpd
