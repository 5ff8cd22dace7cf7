#pragma once
// Reading and changing one entry of a dictionary file by its slash-separated path
// ("walls/lower/velocity"), as OpenFOAM's foamDictionary does; used by Allrun scripts and sweeps.
#include <string>

namespace dpd {

// The value text of the entry (a sub-dictionary prints in dictionary syntax). InputError naming the
// file when the path does not exist.
std::string readDictionaryEntry(const std::string& file, const std::string& entryPath);
// Sets the entry (creating missing sub-dictionaries) and rewrites the file atomically. The file is
// rewritten from its parsed form: comments are not kept and #include/$macro are expanded.
void setDictionaryEntry(const std::string& file, const std::string& entryPath, const std::string& value);

}  // namespace dpd
