#pragma once
// The bonds of a run, grouped by chain, and where each bonded particle lies in the particle arrays
// (which the cell sort reorders every step). Chains share no particle, so the bond pass runs its
// chains in parallel and adds each particle's bond forces in the same order whatever the threads.
#include "core/Bonds.hpp"
#include "core/Particles.hpp"

#include <cstdint>
#include <vector>

namespace dpd {

// What one bond pass found.
struct BondPassResult {
    double longest2 = 0.0;   // the longest bond's r^2
    long broken = -1;        // the first bond (in the pass's order) at or beyond the potential's
                             // maxLength, or not finite; -1 when there is none
    double brokenLength = 0.0;
    bool ok() const { return broken < 0; }
};

class ChainBonds {
public:
    ChainBonds() = default;
    // Keeps the bonds' order within each chain; chains in the order of their indices.
    explicit ChainBonds(Bonds bonds);

    bool empty() const { return bonds_.empty(); }
    std::size_t size() const { return bonds_.size(); }
    const Bonds& bonds() const { return bonds_; }
    Bonds& bonds() { return bonds_; }  // the pass follows the vectors
    std::size_t chainCount() const { return chainStart_.empty() ? 0 : chainStart_.size() - 1; }
    std::size_t chainBegin(std::size_t c) const { return chainStart_[c]; }
    std::size_t chainEnd(std::size_t c) const { return chainStart_[c + 1]; }

    // Records where each particle lies now (after a sort). std::invalid_argument when a bonded id is
    // missing from the particles.
    void locate(const Particles& p);
    std::uint32_t indexOf(std::uint64_t id) const { return indexOfId_[id]; }

private:
    Bonds bonds_;
    std::vector<std::size_t> chainStart_;    // bonds of chain c: [chainStart_[c], chainStart_[c + 1])
    std::vector<std::uint32_t> indexOfId_;   // by particle id (kept for the bonded species only)
    std::vector<std::uint8_t> bondedSpecies_;  // 1 for a species holding bonded particles (256 entries)
};

}  // namespace dpd
