#include "parallel/RankChains.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace dpd {

namespace {

template <class Record>
void appendRecord(std::vector<char>& out, const Record& r) {
    const char* bytes = reinterpret_cast<const char*>(&r);
    out.insert(out.end(), bytes, bytes + sizeof r);
}

template <class Record>
std::vector<Record> recordsOf(const std::vector<char>& bytes) {
    if (bytes.size() % sizeof(Record) != 0) throw std::logic_error("RankChains: a message cut inside a record");
    std::vector<Record> out(bytes.size() / sizeof(Record));
    if (!out.empty()) std::memcpy(out.data(), bytes.data(), bytes.size());
    return out;
}

// Every rank's records on the root, in rank order (empty elsewhere).
template <class Record>
std::vector<Record> gatheredRecords(const Communicator& comm, const std::vector<char>& mine) {
    std::vector<char> all;
    std::vector<std::size_t> counts;
    comm.gather(mine, all, counts);
    return recordsOf<Record>(all);
}

}  // namespace

std::vector<std::uint32_t> indexById(const Particles& own, std::uint64_t maxId) {
    std::vector<std::uint32_t> at(maxId + 1, kNotHeld);
    for (std::size_t i = 0; i < own.size(); ++i)
        if (own.id[i] <= maxId) at[own.id[i]] = static_cast<std::uint32_t>(i);
    return at;
}

std::uint64_t maxBondedId(const Bonds& bonds) {
    std::uint64_t maxId = 0;
    for (std::size_t k = 0; k < bonds.size(); ++k) maxId = std::max({maxId, bonds.first[k], bonds.second[k]});
    return maxId;
}

void appendBondVectors(const ChainBonds& bonds, std::uint64_t id, std::vector<char>& out, std::uint64_t& count) {
    const Bonds& b = bonds.bonds();
    for (auto [k, end] = bonds.bondsOf(id); k != end; ++k) {
        appendRecord(out, BondVectorRecord{*k, b.bx[*k], b.by[*k], b.bz[*k]});
        ++count;
    }
}

void takeBondVectors(const char* at, std::uint64_t n, ChainBonds& bonds) {
    Bonds& b = bonds.bonds();
    for (std::uint64_t r = 0; r < n; ++r, at += sizeof(BondVectorRecord)) {
        BondVectorRecord v;
        std::memcpy(&v, at, sizeof v);
        if (v.bond >= b.size()) throw std::logic_error("takeBondVectors: a bond index beyond the bonds");
        b.bx[v.bond] = v.x;
        b.by[v.bond] = v.y;
        b.bz[v.bond] = v.z;
    }
}

BondPassResult agreedOverRanks(const Communicator& comm, const BondPassResult& mine) {
    // The first broken bond is the largest of the negated indices (none: the lowest double).
    const double none = std::numeric_limits<double>::lowest();
    double values[2] = {mine.longest2, mine.broken >= 0 ? -static_cast<double>(mine.broken) : none};
    comm.max(values, 2);
    BondPassResult agreed;
    agreed.longest2 = values[0];
    if (values[1] == none) return agreed;
    agreed.broken = static_cast<long>(-values[1]);
    agreed.brokenLength = comm.max(agreed.broken == mine.broken ? mine.brokenLength : kUnseenBondLength);
    return agreed;
}

Bonds bondsOnRoot(const Communicator& comm, const Bonds& bonds, const Particles& own) {
    const std::vector<std::uint32_t> at = indexById(own, maxBondedId(bonds));
    std::vector<char> mine;
    for (std::size_t k = 0; k < bonds.size(); ++k)
        if (at[bonds.first[k]] != kNotHeld) appendRecord(mine, BondVectorRecord{k, bonds.bx[k], bonds.by[k], bonds.bz[k]});
    const std::vector<BondVectorRecord> all = gatheredRecords<BondVectorRecord>(comm, mine);
    if (!comm.isRoot()) return bonds;
    if (all.size() != bonds.size())
        throw std::logic_error("bondsOnRoot: " + std::to_string(all.size()) + " bond vectors came for " +
                               std::to_string(bonds.size()) + " bonds");
    Bonds whole = bonds;
    for (const BondVectorRecord& v : all) {
        whole.bx[v.bond] = v.x;
        whole.by[v.bond] = v.y;
        whole.bz[v.bond] = v.z;
    }
    return whole;
}

std::vector<Eigen::Vector3d> positionsOnRoot(const Communicator& comm, const std::vector<std::uint64_t>& ids,
                                             const Particles& own) {
    struct PositionRecord {
        std::uint64_t slot;
        double x, y, z;
    };
    const std::uint64_t maxId = ids.empty() ? 0 : *std::max_element(ids.begin(), ids.end());
    const std::vector<std::uint32_t> at = indexById(own, maxId);
    std::vector<char> mine;
    for (std::size_t k = 0; k < ids.size(); ++k)
        if (const std::uint32_t i = at[ids[k]]; i != kNotHeld)
            appendRecord(mine, PositionRecord{k, own.rx[i], own.ry[i], own.rz[i]});
    const std::vector<PositionRecord> all = gatheredRecords<PositionRecord>(comm, mine);
    if (!comm.isRoot()) return {};
    if (all.size() != ids.size())
        throw std::logic_error("positionsOnRoot: " + std::to_string(all.size()) + " positions came for " +
                               std::to_string(ids.size()) + " particles");
    std::vector<Eigen::Vector3d> out(ids.size());
    for (const PositionRecord& r : all) out[r.slot] = {r.x, r.y, r.z};
    return out;
}

}  // namespace dpd
