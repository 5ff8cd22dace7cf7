#pragma once
// Does the fluid connect across the periodic box along an axis (can a flow driven along it pass)?
#include "geometry/SolidFlags.hpp"

namespace dpd {

// True when some face-connected cluster of fluid cells wraps around the periodic box along `axis`:
// a flood fill that records, for every cell it reaches, how many times it crossed the periodic
// boundary along `axis`; reaching a cell a second time with a different count means the cluster
// joins itself across the box. The other axes wrap too (the box is periodic along all of them) but
// their crossings are not counted. An axis with a single cell percolates when any cell is fluid.
bool fluidPercolates(const SolidFlags& flags, int axis);

}  // namespace dpd
