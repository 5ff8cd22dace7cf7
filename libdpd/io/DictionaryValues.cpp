#include "io/Dictionary.hpp"

#include "core/Axis.hpp"
#include "core/Error.hpp"
#include "io/DictionaryDetail.hpp"

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

using detail::DictValue;
using detail::formatWord;
using detail::joinTokens;

namespace {

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

}  // namespace

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

}  // namespace dpd
