#pragma once
// Reads a dictionary's text into Dictionary entries (OpenFOAM syntax: keywords, sub-dictionaries,
// lists, comments, #include, $macro). Macros and #include are resolved while reading, as in OpenFOAM,
// so a macro sees the entries above it in this and the enclosing dictionaries.
#include "io/Dictionary.hpp"

#include <string>

namespace dpd {

// Parses `text`, read from `file` (messages and relative #include paths), into `root`.
void parseDictionaryText(const std::string& text, const std::string& file, Dictionary& root);

}  // namespace dpd
