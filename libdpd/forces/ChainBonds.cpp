#include "forces/ChainBonds.hpp"

#include <algorithm>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

namespace dpd {

namespace {

constexpr std::uint32_t kNowhere = std::numeric_limits<std::uint32_t>::max();

Bonds reordered(const Bonds& b, const std::vector<std::size_t>& order) {
    Bonds out;
    for (std::size_t k : order) out.add(b.first[k], b.second[k], b.chain[k], b.vector(k));
    return out;
}

}  // namespace

ChainBonds::ChainBonds(Bonds bonds) {
    std::vector<std::size_t> order(bonds.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return bonds.chain[a] < bonds.chain[b]; });
    bonds_ = reordered(bonds, order);
    for (std::size_t k = 0; k < bonds_.size(); ++k)
        if (k == 0 || bonds_.chain[k] != bonds_.chain[k - 1]) chainStart_.push_back(k);
    if (!bonds_.empty()) chainStart_.push_back(bonds_.size());
}

void ChainBonds::holdPartOnly() {
    if (bonds_.empty()) return;
    if (indexOfId_.empty()) throw std::logic_error("ChainBonds::holdPartOnly before the first locate");
    partOnly_ = true;
    // The bonds of each id, in bond order (a counting sort by id).
    bondsOfIdStart_.assign(indexOfId_.size() + 1, 0);
    for (std::size_t k = 0; k < bonds_.size(); ++k)
        for (std::uint64_t id : {bonds_.first[k], bonds_.second[k]}) ++bondsOfIdStart_[id + 1];
    for (std::size_t id = 0; id + 1 < bondsOfIdStart_.size(); ++id) bondsOfIdStart_[id + 1] += bondsOfIdStart_[id];
    bondsOfId_.assign(bondsOfIdStart_.back(), 0);
    std::vector<std::uint32_t> fill(bondsOfIdStart_.begin(), bondsOfIdStart_.end() - 1);
    for (std::size_t k = 0; k < bonds_.size(); ++k)
        for (std::uint64_t id : {bonds_.first[k], bonds_.second[k]}) bondsOfId_[fill[id]++] = static_cast<std::uint32_t>(k);
}

void ChainBonds::locate(const Particles& p) {
    if (bonds_.empty()) return;
    const std::size_t n = p.size();
    if (n >= kNowhere) throw std::invalid_argument("bonds: more particles than 32-bit indices can address");
    if (indexOfId_.empty()) {
        // Ids are dense in practice (the builders number particles 0, 1, ...): a table by id is the
        // cheapest lookup.
        const std::uint64_t maxId = n ? *std::max_element(p.id.begin(), p.id.end()) : 0;
        if (maxId > 16 * n + (1u << 20))
            throw std::invalid_argument("bonds: particle ids up to " + std::to_string(maxId) + " for " + std::to_string(n) +
                                        " particles are too sparse to index");
        indexOfId_.assign(maxId + 1, kNowhere);
        for (std::size_t i = 0; i < n; ++i) indexOfId_[p.id[i]] = static_cast<std::uint32_t>(i);
        for (std::size_t k = 0; k < bonds_.size(); ++k)
            for (std::uint64_t id : {bonds_.first[k], bonds_.second[k]}) {
                if (id >= indexOfId_.size() || indexOfId_[id] == kNowhere)
                    throw std::invalid_argument("bonds: particle " + std::to_string(id) + " is bonded but missing");
                const std::uint8_t species = p.species[indexOfId_[id]];
                if (species >= bondedSpecies_.size()) bondedSpecies_.resize(species + 1, 0);
                bondedSpecies_[species] = 1;
            }
        bondedSpecies_.resize(256, 0);
        return;
    }
    // Only the particles of species that hold bonded ones: in a solution a scan of the species
    // bytes and a few writes, instead of a write per particle (the table's other entries go stale,
    // and are never read).
    const long count = static_cast<long>(n);
    const std::uint64_t* ids = p.id.data();
    const std::uint8_t* species = p.species.data();
    const std::uint8_t* bonded = bondedSpecies_.data();
    std::uint32_t* index = indexOfId_.data();
#pragma omp parallel for schedule(static)
    for (long i = 0; i < count; ++i)
        if (bonded[species[i]]) index[ids[i]] = static_cast<std::uint32_t>(i);
}

}  // namespace dpd
