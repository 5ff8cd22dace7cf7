#pragma once
// The bin layout of a binnedProfile function (controlDict) or of system/profileBinsDict:
//
//   axis z; nBins 40; min -5; max 5;                 // bins along one axis (min/max default: the box)
//   axes (x z); nBins (160 80); min (-30 -15); max (30 15);   // a 2-D grid of bins
//   sections (-25.5 0 25.5);   // 2-D grid only, optional: 1-D profiles along the second axis in the
//                              // column of bins holding each position along the first axis
//
// Errors are InputErrors naming the dictionary, the line and the keyword.
#include "core/Box.hpp"
#include "sampling/BinAccumulator.hpp"

#include <string>
#include <vector>

namespace dpd {

class Dictionary;

// The keywords the layout uses, for checkKeys.
std::vector<std::string> binLayoutKeys();
BinLayout readBinLayout(const Dictionary& d, const Box& box);
// The sections of a 2-D layout, each within [lo, hi) of the first axis; empty when not given.
std::vector<double> readSections(const Dictionary& d, const BinLayout& layout);
// The measure of the box across the bins: volume / length (one axis) or volume / (length1 length2).
double binCrossSection(const BinLayout& layout, const Box& box);

}  // namespace dpd
