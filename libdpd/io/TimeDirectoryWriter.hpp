#pragma once
// A time directory appears whole or not at all: it is filled under a name that is not a time
// (".writing-<time>", which every reader of times passes over) and then renamed into place; one that
// already exists is swapped out atomically. A run killed while writing leaves the earlier times and,
// at worst, an unfinished ".writing-" directory, never a time with part of its files.
#include <functional>
#include <string>

namespace dpd {

// Writes <caseDir>/<time> through fill(directory), which writes its files into the directory given.
void writeTimeDirectory(const std::string& caseDir, const std::string& time,
                        const std::function<void(const std::string& directory)>& fill);
// Removes what a killed writer left (".writing-*" and ".replaced-*" directories).
void removeUnfinishedTimeDirectories(const std::string& caseDir);

}  // namespace dpd
