#pragma once
// The names of the three axes, as case files and tables write them.
#include <string>

namespace dpd {

// "x", "y" or "z" for axis 0, 1 or 2.
inline const char* axisLetter(int axis) { return axis == 0 ? "x" : axis == 1 ? "y" : "z"; }

// 0, 1 or 2 for "x", "y" or "z"; -1 for anything else.
inline int axisFromLetter(const std::string& s) { return s == "x" ? 0 : s == "y" ? 1 : s == "z" ? 2 : -1; }

}  // namespace dpd
