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
    double brokenLength = 0.0;  // kUnseenBondLength: longer than a decomposed run's ghosts reach
    bool ok() const { return broken < 0; }
};
inline constexpr double kUnseenBondLength = -1.0;

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
    // 1 for each species (by index, 256 entries) that holds bonded particles, once located.
    const std::vector<std::uint8_t>& bondedSpecies() const { return bondedSpecies_; }

    // A decomposed run (parallel/SlabDomain): a rank holds its own beads and its ghosts only. After
    // the first locate (every particle present), holdPartOnly() lets later ones find only the
    // particles present; after each sort setOwned() says which are the rank's own. A pass then
    // takes a bond where one of its particles is owned (here()): both ranks of a bond across a
    // face follow its vector, each adding the force to its own particle in one process's order.
    void holdPartOnly();
    bool holdsPartOnly() const { return partOnly_; }
    void setOwned(std::size_t first, std::size_t end) { ownFirst_ = first; ownEnd_ = end; }
    // What a pass on this rank does with bond k, its particles at i and j (indexOf).
    enum class Here { Evaluate, Skip, Beyond };  // Beyond: one is owned, the other further than the ghosts
    Here here(std::size_t k, std::uint32_t i, std::uint32_t j, const Particles& p) const {
        const bool hasI = i < p.size() && p.id[i] == bonds_.first[k], hasJ = j < p.size() && p.id[j] == bonds_.second[k];
        const bool ownsI = hasI && i >= ownFirst_ && i < ownEnd_, ownsJ = hasJ && j >= ownFirst_ && j < ownEnd_;
        if (!ownsI && !ownsJ) return Here::Skip;
        return hasI && hasJ ? Here::Evaluate : Here::Beyond;
    }
    // The bonds (indices into bonds()) a particle belongs to: [first, second). holdPartOnly() only.
    std::pair<const std::uint32_t*, const std::uint32_t*> bondsOf(std::uint64_t id) const {
        if (id + 1 >= bondsOfIdStart_.size()) return {nullptr, nullptr};
        return {bondsOfId_.data() + bondsOfIdStart_[id], bondsOfId_.data() + bondsOfIdStart_[id + 1]};
    }

private:
    Bonds bonds_;
    std::vector<std::size_t> chainStart_;    // bonds of chain c: [chainStart_[c], chainStart_[c + 1])
    std::vector<std::uint32_t> indexOfId_;   // by particle id (kept for the bonded species only)
    std::vector<std::uint8_t> bondedSpecies_;  // 1 for a species holding bonded particles (256 entries)
    bool partOnly_ = false;
    std::size_t ownFirst_ = 0, ownEnd_ = 0;
    std::vector<std::uint32_t> bondsOfIdStart_, bondsOfId_;  // a particle's bonds, by id (holdPartOnly)
};

}  // namespace dpd
