#pragma once
// system/decomposeParDict: how a run under mpirun cuts the box (docs/parallel.md). Optional: without
// it a run on N ranks cuts N slabs along x balanced over the particles.
//
//   numberOfSubdomains 4;        // must be the number of ranks mpirun starts
//   method        slabs;         // planes of cells along x (the one method so far)
//   planes        (3 5 5 7);     // optional: cell planes per rank, in rank order; they add up to the
//                                // box's planes (its length along x over the cutoff, rounded down)
#include "io/Dictionary.hpp"

#include <string>
#include <vector>

namespace dpd {

struct Box;

struct DecomposeSettings {
    std::vector<int> planes;  // per rank; empty: balanced
    Dictionary dict{"decomposeParDict"};
    bool present = false;
};

// Reads <caseDir>/system/decomposeParDict if there is one; an InputError (file, line, keyword) for a
// subdomain count other than `ranks`, an unknown method or key, or a plane list of the wrong length.
DecomposeSettings readDecomposeParDict(const std::string& caseDir, int ranks);
// The per-rank planes checked against the box: they must add up to its planes along x, and each
// rank's hold the ghost planes its neighbours take from it (as many as reach `ghostReach`).
void checkPlanesFitBox(const DecomposeSettings& s, const Box& box, double cutoff, double ghostReach);

}  // namespace dpd
