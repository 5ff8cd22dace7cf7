#pragma once
// The `box { min (...); max (...); }` entry of a builder's dictionary (blockFrozenWallDict,
// randomEquilWallDict): the periodic box a case is built in.
#include "core/Box.hpp"

namespace dpd {

class Dictionary;

// Reads d's `box` sub-dictionary. In 2-D the y axis is inactive and gets a nominal unit extent.
// Every active axis must be at least two cutoffs long (the cell list's minimum); otherwise an
// InputError names the file, line and keyword.
Box readBoxDictionary(const Dictionary& d, int dimension, double cutoff);

}  // namespace dpd
