#pragma once
// Profiles on a 2-D grid of bins (BinLayout with two axes): as VTK XML image data for ParaView (one
// cell per bin, the cells' data density, densityErr, velocity, velocityErr, kT, kTErr, count), and
// cut into 1-D sections along the second axis.
#include "sampling/BinProfile.hpp"

#include <string>

namespace dpd {

// Writes <path> (.vti, ASCII XML) whole or not at all. The grid lies in the box's own axes: the
// bins' first axis along that box axis, the second along its own, one cell thick across.
void writeProfileImage(const std::string& path, const BinLayout& layout, const BinProfile& profile);

// The 1-D profile along the second axis through the column of bins holding `position` along the
// first axis (std::invalid_argument when it lies outside the bins); written as any 1-D table.
BinProfile profileSection(const BinLayout& layout, const BinProfile& profile, double position);

// The file name of a section: <name>_<axis><position>.dat, e.g. velocity_x-25.5.dat.
std::string sectionFileName(const std::string& name, const BinLayout& layout, double position);

}  // namespace dpd
