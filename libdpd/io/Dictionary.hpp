#pragma once
// Case files in OpenFOAM dictionary syntax (system/controlDict, constant/dpdProperties, ...).
//
//     FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }
//     deltaT      0.01;               // keyword value;
//     name        "a b";              // quoted string
//     origin      (0.02 0 0);         // lists, possibly nested: ((0 0) (1 1))
//     walls { lower { velocity (1 0 0); } }   // sub-dictionaries to any depth
//     #include "common"               // path relative to the including file
//     endTime     $deltaT;            // macro: this scope, then enclosing ones; $walls.lower.velocity
//     $defaults;                      // a macro naming a sub-dictionary, as an entry: merges it here
//
// Semantics chosen to match OpenFOAM:
//  - a later duplicate keyword overrides the earlier one and keeps the earlier position; when both are
//    sub-dictionaries they are merged (OpenFOAM's default "#inputMode merge"), keyword by keyword;
//  - macros are expanded while reading, so they see only entries above them;
//  - a FoamFile header at the top of a file stays reachable through found()/subDict() but is skipped
//    by keys(), checkKeys() and toString(); a header inside an #include'd file is dropped.
//
// Every error is an InputError naming the file, the line and, where there is one, the keyword; for a
// sub-dictionary the message also names its scope, e.g. "(in walls/lower)".
#include <Eigen/Core>

#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace dpd {

namespace detail {
struct DictEntry;  // one "keyword value;" or "keyword { ... }"; defined in Dictionary.cpp
struct DictValue;  // an entry's tokens seen by the typed getters
template <class>
inline constexpr bool dictionaryUnsupportedType = false;
}  // namespace detail

class Dictionary {
public:
    Dictionary();
    explicit Dictionary(std::string fileName);  // an empty dictionary that errors attribute to fileName
    Dictionary(const Dictionary&);
    Dictionary(Dictionary&&) noexcept;
    Dictionary& operator=(const Dictionary&);
    Dictionary& operator=(Dictionary&&) noexcept;
    ~Dictionary();

    // InputError(path, 0, "", "cannot open file") when it cannot be read. Warnings (below) are
    // printed on stderr as the file is read, so they come first in a case's log.
    static Dictionary readFile(const std::string& path);
    // fileName is used for messages and as the base directory of relative #include paths.
    static Dictionary parse(const std::string& text, const std::string& fileName);

    // What was read but looks mistaken, e.g. a keyword given twice in one dictionary of one file (the
    // last one is used, as in OpenFOAM; an #include'd default overridden later is not warned about).
    const std::vector<std::string>& warnings() const { return warnings_; }
    const std::string& fileName() const { return file_; }  // the file this dictionary was read from
    int line() const { return line_; }                      // where it opened; 0 at top level
    std::string path() const { return path_; }              // e.g. "walls/lower"; "" at top level

    bool found(const std::string& key) const;
    bool isDict(const std::string& key) const;
    const Dictionary& subDict(const std::string& key) const;  // error if missing or not a dictionary
    std::vector<std::string> keys() const;                    // file order, without FoamFile
    int lineOf(const std::string& key) const;                 // error if missing
    // The value as written (tokens joined by single spaces), e.g. "(0.02 0 0)"; error if missing.
    std::string rawValue(const std::string& key) const;

    // Typed access. A missing keyword or a value of the wrong type is an InputError naming the
    // expected type. Supported T: double, int, long, long long (so std::int64_t on every platform),
    // bool (yes/no/on/off/true/false), std::string (one word or quoted string), std::vector<double>,
    // std::vector<int>, std::vector<std::string> (list of words or strings), Eigen::Vector3d (a list
    // of exactly 3 numbers), std::vector<Eigen::Vector3d>, std::vector<std::vector<double>>.
    // Lists may carry an OpenFOAM length prefix, 3(1 2 3), which must then match.
    template <class T>
    T get(const std::string& key) const;
    template <class T>
    T getOrDefault(const std::string& key, const T& def) const;
    std::string getOrDefault(const std::string& key, const char* def) const;
    // Numbers with the sign check done here: "must be positive" / "must be non-negative".
    template <class T>
    T getPositive(const std::string& key) const;
    template <class T>
    T getNonNegative(const std::string& key) const;
    // A box axis written as its letter: x, y or z -> 0, 1, 2 ("expected x, y or z, not '...'").
    int getAxis(const std::string& key) const;
    // A list (low high) with high > low; lowName and highName word the error ("expected (lower upper)
    // with upper > lower").
    std::pair<double, double> getIncreasingPair(const std::string& key, const std::string& lowName,
                                                const std::string& highName) const;

    // Any keyword of this dictionary that is not in allowed -> InputError "unknown keyword" naming
    // its line and listing the allowed keywords (with a "did you mean" for near misses).
    void checkKeys(const std::vector<std::string>& allowed) const;
    // InputError about a keyword of this dictionary (range checks by callers): names the file and
    // line of the keyword, or of this dictionary when the keyword is absent.
    [[noreturn]] void fail(const std::string& key, const std::string& message) const;

    // Editing. set() takes value text in dictionary syntax, e.g. "0.01", "(1 0 0)", "\"a b\"";
    // setValue() writes a typed value (doubles in shortest round-trip form).
    void set(const std::string& key, const std::string& valueTokens);
    template <class T>
    void setValue(const std::string& key, const T& value);
    void setValue(const std::string& key, const char* value);
    Dictionary& subDictOrCreate(const std::string& key);  // error if key holds a plain value
    bool remove(const std::string& key);                  // false when it was not there

    // The body in OpenFOAM layout (keywords padded to 16 columns, 4 spaces per level), without the
    // FoamFile header. Reading it back gives the same values.
    std::string toString(int indent = 0) const;

private:
    friend class DictionaryParser;

    const detail::DictEntry* findEntry(const std::string& key) const;
    detail::DictEntry* findEntry(const std::string& key);
    bool isHeader(const detail::DictEntry& e) const;
    detail::DictValue valueOf(const std::string& key, const std::string& expected) const;
    [[noreturn]] void missing(const std::string& key, const std::string& expected) const;
    void insert(detail::DictEntry entry);
    void mergeFrom(const Dictionary& other);
    void rescope(const std::string& path);
    std::string scopeNote() const;

    std::string file_;
    int line_ = 0;
    std::string path_;
    std::vector<detail::DictEntry> entries_;
    std::vector<std::string> warnings_;  // the top-level dictionary's, from the whole file
};

// Unsupported types fail at compile time; the supported ones are specialised in Dictionary.cpp.
template <class T>
T Dictionary::get(const std::string&) const {
    static_assert(detail::dictionaryUnsupportedType<T>, "Dictionary::get: unsupported type");
}
template <class T>
void Dictionary::setValue(const std::string&, const T&) {
    static_assert(detail::dictionaryUnsupportedType<T>, "Dictionary::setValue: unsupported type");
}

template <> double Dictionary::get<double>(const std::string& key) const;
template <> int Dictionary::get<int>(const std::string& key) const;
template <> long Dictionary::get<long>(const std::string& key) const;
template <> long long Dictionary::get<long long>(const std::string& key) const;
template <> bool Dictionary::get<bool>(const std::string& key) const;
template <> std::string Dictionary::get<std::string>(const std::string& key) const;
template <> std::vector<double> Dictionary::get<std::vector<double>>(const std::string& key) const;
template <> std::vector<int> Dictionary::get<std::vector<int>>(const std::string& key) const;
template <> std::vector<std::string> Dictionary::get<std::vector<std::string>>(const std::string& key) const;
template <> Eigen::Vector3d Dictionary::get<Eigen::Vector3d>(const std::string& key) const;
template <> std::vector<Eigen::Vector3d> Dictionary::get<std::vector<Eigen::Vector3d>>(
    const std::string& key) const;
template <> std::vector<std::vector<double>> Dictionary::get<std::vector<std::vector<double>>>(
    const std::string& key) const;

template <> void Dictionary::setValue<double>(const std::string& key, const double& value);
template <> void Dictionary::setValue<int>(const std::string& key, const int& value);
template <> void Dictionary::setValue<long>(const std::string& key, const long& value);
template <> void Dictionary::setValue<long long>(const std::string& key, const long long& value);
template <> void Dictionary::setValue<bool>(const std::string& key, const bool& value);
template <> void Dictionary::setValue<std::string>(const std::string& key, const std::string& value);
template <> void Dictionary::setValue<std::vector<double>>(const std::string& key,
                                                           const std::vector<double>& value);
template <> void Dictionary::setValue<std::vector<int>>(const std::string& key, const std::vector<int>& value);
template <> void Dictionary::setValue<std::vector<std::string>>(const std::string& key,
                                                                const std::vector<std::string>& value);
template <> void Dictionary::setValue<Eigen::Vector3d>(const std::string& key, const Eigen::Vector3d& value);

template <class T>
T Dictionary::getOrDefault(const std::string& key, const T& def) const {
    return found(key) ? get<T>(key) : def;
}

template <class T>
T Dictionary::getPositive(const std::string& key) const {
    static_assert(std::is_arithmetic_v<T>, "Dictionary::getPositive needs a number type");
    const T value = get<T>(key);
    if (!(value > T(0))) fail(key, "must be positive, got " + rawValue(key));
    return value;
}

template <class T>
T Dictionary::getNonNegative(const std::string& key) const {
    static_assert(std::is_arithmetic_v<T>, "Dictionary::getNonNegative needs a number type");
    const T value = get<T>(key);
    if (value < T(0)) fail(key, "must be non-negative, got " + rawValue(key));
    return value;
}

// Writes dict with a FoamFile header (object = the file's name) to path atomically: the text goes to
// "<path>.tmp<pid>" first and is then renamed over path, so a concurrent reader sees either the old
// or the new file, never half of one. Throws IoError when it cannot write.
void writeDictionaryFile(const std::string& path, const Dictionary& dict);

}  // namespace dpd
