#pragma once
// The pair virial per bin, for the stress profile (docs/analysis.md section 5): a traversal of all
// interacting pairs through the system's cell list, done only at sample steps and apart from the hot
// pair loop of the integrator.
//
// Each pair's virial W_ab = r_ij,a F_ij,b (F_ij the force on i from j, r_ij = r_i - r_j) is shared
// between the bins by the Irving-Kirkwood rule: each bin receives the fraction of the segment i-j
// that lies inside it (measured along the bin axis). Why not half to each particle's bin: next to a
// wall the density is layered on a scale finer than the cutoff, and only the segment rule makes the
// bin stress the average of the momentum flux through the planes of the bin, so that the momentum
// balance d sigma_ab / dx_b = -rho g_a holds bin by bin (tests/sampling/StressProfileTest.cpp).
//
// The forces are the DPD conservative and dissipative forces at the sampled positions and velocities.
// The random force is left out: its noise zeta_ij of this step is drawn independently of the
// positions, so its virial averages to zero exactly and would only add variance.
//
// Bonds count too: each spring's r_ij F_ij shared along its segment in the same way (its force is
// conservative and exact at the sampled positions). With bondedPairs other than `dpd all` the stress
// sampler refuses to run (BinnedProfile::capabilities): the traversal would count the terms taken back.
//
// Every interacting pair counts (fluid-wall pairs carry the wall's stress into the fluid), whatever
// species the profile bins for its other fields. Deterministic on any number of threads: each slab
// of cells sums into its own array, and the slabs are added in order. In a decomposed run each rank
// traverses the pairs of its own planes, with a copy of the next rank's first plane (the half stencil
// goes up along x), and the bonds whose first particle it owns: every pair and bond once over the
// ranks, whose sums the profile adds (equal to one process's to rounding).
#include "core/Particles.hpp"
#include "neighbour/CellList.hpp"
#include "sampling/BinAccumulator.hpp"

#include <vector>

namespace dpd {

class System;

// What a decomposed run's traversal builds at each sample, kept by the sampler so that a sample
// allocates nothing new: the rank's particles with the next rank's first plane, their cell list.
struct PairVirialWork {
    Particles local;
    CellList cells;
};

// The virial sums per bin (nBins tensors xx yy zz xy xz yz) at the system's current state. The
// particles must be sorted by the system's cell list (as they are after a step).
std::vector<SymmetricTensor> binnedPairVirial(const System& sys, const BinLayout& layout);
std::vector<SymmetricTensor> binnedPairVirial(const System& sys, const BinLayout& layout, PairVirialWork& work);

// The Irving-Kirkwood share of a segment from coordinate a to b (any order, |b - a| < box length)
// that falls in each bin, added to `share` (nBins), weighted by `weight`; the segment may cross the
// periodic boundary of [boxLo, boxLo + boxLength). A segment of zero length gives all to its bin.
void addSegmentShares(const BinLayout& layout, double boxLo, double boxLength, double a, double b,
                      std::vector<double>& share, double weight = 1.0);

}  // namespace dpd
