#include "io/DictionaryEdit.hpp"

#include "core/Error.hpp"
#include "io/Dictionary.hpp"

#include <sstream>
#include <vector>

namespace dpd {

namespace {

std::vector<std::string> splitPath(const std::string& path) {
    std::vector<std::string> parts;
    std::stringstream ss(path);
    std::string item;
    while (std::getline(ss, item, '/'))
        if (!item.empty()) parts.push_back(item);
    if (parts.empty()) throw std::invalid_argument("empty entry path");
    return parts;
}

}  // namespace

std::string readDictionaryEntry(const std::string& file, const std::string& entryPath) {
    const Dictionary top = Dictionary::readFile(file);
    const std::vector<std::string> parts = splitPath(entryPath);
    const Dictionary* d = &top;
    for (std::size_t k = 0; k + 1 < parts.size(); ++k) d = &d->subDict(parts[k]);
    const std::string& key = parts.back();
    if (!d->found(key)) throw InputError(file, d->line(), key, "no entry '" + entryPath + "'");
    if (d->isDict(key)) return "{\n" + d->subDict(key).toString(1) + "}";
    return d->rawValue(key);
}

void setDictionaryEntry(const std::string& file, const std::string& entryPath, const std::string& value) {
    Dictionary top = Dictionary::readFile(file);
    const std::vector<std::string> parts = splitPath(entryPath);
    Dictionary* d = &top;
    for (std::size_t k = 0; k + 1 < parts.size(); ++k) d = &d->subDictOrCreate(parts[k]);
    d->set(parts.back(), value);
    writeDictionaryFile(file, top);
}

}  // namespace dpd
