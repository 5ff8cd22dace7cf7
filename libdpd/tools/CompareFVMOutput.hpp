#pragma once
// What compareFVM writes and prints for one time: compare.dat (a dictionary: field and line metrics,
// Darcy's numbers of a 2-D grid), profiles.dat (the compared points, DPD and FVM) and the log's lines.
#include "io/Dictionary.hpp"
#include "tools/CompareFVMTool.hpp"

#include <iosfwd>
#include <string>

namespace dpd {

Dictionary compareFVMDictionary(const CompareFVMResult& r);
std::string compareFVMProfilesText(const CompareFVMResult& r);
void printCompareFVM(std::ostream& out, const CompareFVMResult& r);

}  // namespace dpd
