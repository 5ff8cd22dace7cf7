#include "io/Dictionary.hpp"

#include "core/Axis.hpp"
#include "core/Error.hpp"
#include "io/AtomicFile.hpp"
#include "io/DictionaryDetail.hpp"
#include "io/DictionaryParser.hpp"

#include <iostream>
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

namespace dpd {

using detail::DictEntry;
using detail::DictValue;
using detail::formatWord;
using detail::joinPath;
using detail::joinTokens;
using detail::joinWords;
using detail::kKeywordColumn;
using detail::readText;
using detail::suggestion;

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
    Dictionary d = parse(text, path);
    for (const std::string& w : d.warnings()) std::cerr << "Warning: " << w << "\n";
    return d;
}

Dictionary Dictionary::parse(const std::string& text, const std::string& fileName) {
    Dictionary root(fileName);
    parseDictionaryText(text, fileName, root);
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
