#include "io/SnapshotBonds.hpp"

#include "core/Error.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

namespace dpd {

namespace {

using RowOfId = std::unordered_map<std::uint64_t, std::size_t>;

RowOfId rowsOfIds(const Particles& p) {
    RowOfId rows;
    rows.reserve(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) rows.emplace(p.id[i], i);
    return rows;
}

std::vector<std::int64_t> particleChains(const Snapshot& s, const RowOfId& rows) {
    std::vector<std::int64_t> chain(s.particles.size(), -1);
    for (std::size_t k = 0; k < s.bonds.size(); ++k) {
        chain[rows.at(s.bonds.first[k])] = s.bonds.chain[k];
        chain[rows.at(s.bonds.second[k])] = s.bonds.chain[k];
    }
    return chain;
}

[[noreturn]] void fail(const Hdf5Reader& file, const std::string& message) { throw IoError(file.path() + ": " + message); }

std::string row(const char* dataset, std::size_t k) { return "dataset '" + std::string(dataset) + "' row " + std::to_string(k); }

// The stored vector joins the two positions up to whole box lengths along each periodic axis.
bool joinsPositions(const Box& box, const Eigen::Vector3d& vector, const Eigen::Vector3d& difference) {
    const Eigen::Vector3d length = box.length();
    for (int a = 0; a < 3; ++a) {
        if (!box.isActiveAxis(a)) continue;
        const double images = (vector[a] - difference[a]) / length[a];
        if (!(std::abs(images - std::round(images)) <= 1e-6)) return false;
    }
    return true;
}

void readBondArrays(const Hdf5Reader& file, Bonds& b) {
    std::vector<hsize_t> dims;
    const std::vector<std::uint64_t> pairs = file.readUInt64(bondPairsName, &dims);
    if (dims.size() != 2 || dims[1] != 2) fail(file, "dataset '" + std::string(bondPairsName) + "' is not of shape (M, 2)");
    const std::size_t m = dims[0];
    const std::vector<double> vectors = file.readDoubles(bondVectorName, &dims);
    if (dims != std::vector<hsize_t>{m, 3}) fail(file, "dataset '" + std::string(bondVectorName) + "' is not of shape (M, 3) with M = " + std::to_string(m));
    const std::vector<std::int64_t> chains = file.readInt64(bondChainName, &dims);
    if (dims != std::vector<hsize_t>{m}) fail(file, "dataset '" + std::string(bondChainName) + "' is not of shape (M) with M = " + std::to_string(m));
    for (std::size_t k = 0; k < m; ++k)
        b.add(pairs[2 * k], pairs[2 * k + 1], chains[k], {vectors[3 * k], vectors[3 * k + 1], vectors[3 * k + 2]});
}

void requireValidBond(const Hdf5Reader& file, const Snapshot& s, const RowOfId& rows, std::size_t k) {
    const Bonds& b = s.bonds;
    const auto i = rows.find(b.first[k]), j = rows.find(b.second[k]);
    if (i == rows.end() || j == rows.end())
        fail(file, row(bondPairsName, k) + " joins id " + std::to_string(i == rows.end() ? b.first[k] : b.second[k]) +
                       ", which no particle has");
    if (b.first[k] == b.second[k]) fail(file, row(bondPairsName, k) + " joins particle " + std::to_string(b.first[k]) + " to itself");
    if (b.chain[k] < 0) fail(file, row(bondChainName, k) + " holds a negative chain index");
    const Eigen::Vector3d v = b.vector(k);
    const Particles& p = s.particles;
    const Eigen::Vector3d d(p.rx[j->second] - p.rx[i->second], p.ry[j->second] - p.ry[i->second],
                            p.rz[j->second] - p.rz[i->second]);
    if (!v.allFinite() || !joinsPositions(s.box, v, d)) {
        std::ostringstream os;
        os << row(bondVectorName, k) << " holds (" << v.transpose() << "), which does not join particles "
           << b.first[k] << " and " << b.second[k] << " (their positions differ by (" << d.transpose()
           << ") up to whole box lengths)";
        fail(file, os.str());
    }
}

// Each particle lies in one chain: the bond forces of different chains are then added in parallel.
void requireOneChainEach(const Hdf5Reader& file, const Bonds& b) {
    std::unordered_map<std::uint64_t, std::int64_t> chainOf;
    for (std::size_t k = 0; k < b.size(); ++k)
        for (std::uint64_t id : {b.first[k], b.second[k]}) {
            const auto [it, added] = chainOf.emplace(id, b.chain[k]);
            if (!added && it->second != b.chain[k])
                fail(file, row(bondChainName, k) + ": particle " + std::to_string(id) + " is in chains " +
                               std::to_string(it->second) + " and " + std::to_string(b.chain[k]));
        }
}

}  // namespace

void checkBondsConsistent(const Snapshot& s) {
    const Bonds& b = s.bonds;
    const std::size_t m = b.size();
    if (b.second.size() != m || b.chain.size() != m || b.bx.size() != m || b.by.size() != m || b.bz.size() != m)
        throw std::invalid_argument("writeSnapshot: the bond arrays differ in length");
    const RowOfId rows = rowsOfIds(s.particles);
    for (std::size_t k = 0; k < m; ++k)
        if (!rows.count(b.first[k]) || !rows.count(b.second[k]))
            throw std::invalid_argument("writeSnapshot: bond " + std::to_string(k) + " joins a particle the snapshot does not hold");
}

void writeBonds(Hdf5Writer& file, const Snapshot& s) {
    const Bonds& b = s.bonds;
    if (b.empty()) return;
    const hsize_t m = b.size();
    const RowOfId rows = rowsOfIds(s.particles);
    std::vector<std::uint64_t> pairs(2 * m);
    std::vector<std::int64_t> connectivity(2 * m);
    std::vector<double> vectors(3 * m);
    for (std::size_t k = 0; k < m; ++k) {
        pairs[2 * k] = b.first[k];
        pairs[2 * k + 1] = b.second[k];
        connectivity[2 * k] = static_cast<std::int64_t>(rows.at(b.first[k]));
        connectivity[2 * k + 1] = static_cast<std::int64_t>(rows.at(b.second[k]));
        vectors[3 * k] = b.bx[k];
        vectors[3 * k + 1] = b.by[k];
        vectors[3 * k + 2] = b.bz[k];
    }
    file.writeUInt64(bondPairsName, pairs, {m, 2});
    file.writeDoubles(bondVectorName, vectors, {m, 3});
    file.writeInt64(bondChainName, b.chain);
    file.writeInt64(particleChainName, particleChains(s, rows));
    file.writeInt64(bondConnectivityName, connectivity, {m, 2});
}

void readBonds(const Hdf5Reader& file, Snapshot& s) {
    if (!file.has(bondPairsName)) return;
    readBondArrays(file, s.bonds);
    const RowOfId rows = rowsOfIds(s.particles);
    for (std::size_t k = 0; k < s.bonds.size(); ++k) requireValidBond(file, s, rows, k);
    requireOneChainEach(file, s.bonds);
}

}  // namespace dpd
