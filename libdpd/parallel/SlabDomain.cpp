#include "parallel/SlabDomain.hpp"

#include "parallel/ParticleRecord.hpp"

#include <algorithm>
#include <cstring>

namespace dpd {

namespace {

// Keeps particles [begin, end) of p.
template <class Array>
void keepRange(Array& a, std::size_t begin, std::size_t end) {
    if (begin > 0) std::copy(a.begin() + static_cast<long>(begin), a.begin() + static_cast<long>(end), a.begin());
    a.resize(end - begin);
}

void keepRange(Particles& p, std::size_t begin, std::size_t end) {
    for (auto* a : {&p.rx, &p.ry, &p.rz, &p.vx, &p.vy, &p.vz, &p.fx, &p.fy, &p.fz}) keepRange(*a, begin, end);
    keepRange(p.id, begin, end);
    keepRange(p.species, begin, end);
}

// Removes the particles at the given indices (increasing), the others kept in their order: the runs
// between them moved whole (leavers are few, and most lie in the slab's first and last planes).
template <class Array>
void removeIndices(Array& a, const std::vector<std::size_t>& gone) {
    if (gone.empty()) return;
    auto to = a.begin() + static_cast<long>(gone[0]);
    for (std::size_t k = 0; k < gone.size(); ++k) {
        const auto from = a.begin() + static_cast<long>(gone[k] + 1);
        const auto end = k + 1 < gone.size() ? a.begin() + static_cast<long>(gone[k + 1]) : a.end();
        to = std::copy(from, end, to);
    }
    a.resize(a.size() - gone.size());
}

void removeIndices(Particles& p, const std::vector<std::size_t>& gone) {
    for (auto* a : {&p.rx, &p.ry, &p.rz, &p.vx, &p.vy, &p.vz, &p.fx, &p.fy, &p.fz}) removeIndices(*a, gone);
    removeIndices(p.id, gone);
    removeIndices(p.species, gone);
}

// What goes to one rank in a migration: a count of particles and of deferred crossings, then both.
struct MigrationHeader {
    std::uint64_t particles = 0, deferred = 0;
};

}  // namespace

SlabDomain::SlabDomain(const Communicator& comm, SlabDecomposition slabs) : comm_(&comm), slabs_(std::move(slabs)) {}

std::shared_ptr<SlabDomain> SlabDomain::balanced(const Communicator& comm, const CellList& cells, const Particles& p,
                                                 const std::vector<std::uint8_t>& frozenOfSpecies) {
    std::vector<double> weights(static_cast<std::size_t>(cells.cellsPerAxis()[0]), 0.0);
    const SlabDomain probe(comm, SlabDecomposition(cells.cellsPerAxis()[0]));
    for (std::size_t i = 0; i < p.size(); ++i)
        weights[probe.planeOf(cells, p.rx[i])] += frozenOfSpecies[p.species[i]] ? SlabDecomposition::kFrozenWeight : 1.0;
    return std::make_shared<SlabDomain>(comm, SlabDecomposition::balanced(weights, comm.size()));
}

int SlabDomain::planeOf(const CellList& cells, double x) const { return cells.axisCell(cells.box().wrap(x, 0), 0); }

std::vector<std::uint8_t> SlabDomain::homePlanes() const {
    const int n = slabs_.planes();
    std::vector<std::uint8_t> home(static_cast<std::size_t>(n), 0);
    for (int ix = firstPlane() - 1; ix < endPlane(); ++ix) home[static_cast<std::size_t>((ix + n) % n)] = 1;
    return home;
}

void SlabDomain::keepOwned(Particles& p, const CellList& cells) const {
    std::vector<std::size_t> others;
    const int lo = firstPlane(), hi = endPlane();
    for (std::size_t i = 0; i < p.size(); ++i) {
        const int plane = planeOf(cells, p.rx[i]);
        if (plane < lo || plane >= hi) others.push_back(i);
    }
    removeIndices(p, others);
}

void SlabDomain::migrate(Particles& p, const Ranges& own, const CellList& cells, std::vector<DeferredCrossing>& deferred,
                         Particles& fromLower, std::vector<std::uint32_t>& leavers) const {
    const int ranks = comm_->size(), me = comm_->rank();
    const int lo = firstPlane(), hi = endPlane();
    std::vector<std::vector<char>> records(ranks), crossings(ranks);
    std::vector<MigrationHeader> headers(ranks);
    std::vector<std::uint8_t> deferredLeaves(deferred.size(), 0);
    leavers.clear();
    // Every particle's plane in one flat pass (the order is the arrays'), then the leavers in
    // one process's order.
    const long n = static_cast<long>(p.size());
    planes_.resize(p.size());
    const double* rx = p.rx.data();
    std::int32_t* planes = planes_.data();
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i) planes[i] = planeOf(cells, rx[i]);
    for (const auto& [first, end] : own)
        for (std::uint32_t i = first; i < end; ++i) {
            const int plane = planes[i];
            if (plane >= lo && plane < hi) continue;
            const int to = slabs_.ownerOf(plane);
            leavers.push_back(i);
            appendRecord(p, i, records[to]);
            ++headers[to].particles;
            const auto d = std::lower_bound(deferred.begin(), deferred.end(), p.id[i],
                                            [](const DeferredCrossing& c, std::uint64_t id) { return c.id < id; });
            if (d != deferred.end() && d->id == p.id[i]) {
                const std::size_t at = crossings[to].size();
                crossings[to].resize(at + sizeof(DeferredCrossing));
                std::memcpy(crossings[to].data() + at, &*d, sizeof(DeferredCrossing));
                deferredLeaves[static_cast<std::size_t>(d - deferred.begin())] = 1;
                ++headers[to].deferred;
            }
        }
    std::vector<std::vector<char>> send(ranks);
    for (int r = 0; r < ranks; ++r) {
        send[r].resize(sizeof(MigrationHeader));
        std::memcpy(send[r].data(), &headers[r], sizeof(MigrationHeader));
        send[r].insert(send[r].end(), records[r].begin(), records[r].end());
        send[r].insert(send[r].end(), crossings[r].begin(), crossings[r].end());
    }
    std::vector<char> received;
    std::vector<std::size_t> counts;
    comm_->exchange(send, received, counts);

    std::size_t kept = 0;
    for (std::size_t k = 0; k < deferred.size(); ++k)
        if (!deferredLeaves[k]) deferred[kept++] = deferred[k];
    deferred.resize(kept);
    fromLower = Particles();
    const char* at = received.data();
    for (int r = 0; r < ranks; ++r) {
        const char* next = at + counts[r];
        MigrationHeader h;
        std::memcpy(&h, at, sizeof h);
        at += sizeof h;
        if (r != me) appendRecords(at, h.particles, r < me ? fromLower : p);
        at += h.particles * sizeof(ParticleRecord);
        for (std::uint64_t k = 0; k < h.deferred; ++k, at += sizeof(DeferredCrossing)) {
            DeferredCrossing d;
            std::memcpy(&d, at, sizeof d);
            deferred.push_back(d);
        }
        at = next;
    }
    std::sort(deferred.begin(), deferred.end(), [](const DeferredCrossing& a, const DeferredCrossing& b) { return a.id < b.id; });
}

void SlabDomain::addGhosts(const Particles& fromLower, Particles& p, const Ranges& own, const CellList& cells) const {
    const int ranks = comm_->size(), n = slabs_.planes();
    const int lo = firstPlane(), hi = endPlane();
    const int below = slabs_.ownerOf((lo - 1 + n) % n), above = slabs_.ownerOf(hi % n);
    // The planes of those that came in; the slab's own as migrate found them.
    std::vector<std::int32_t> lowerPlanes(fromLower.size());
    for (std::size_t i = 0; i < fromLower.size(); ++i) lowerPlanes[i] = planeOf(cells, fromLower.rx[i]);
    const std::size_t known = planes_.size();
    planes_.resize(p.size());
    for (std::size_t i = known; i < p.size(); ++i) planes_[i] = planeOf(cells, p.rx[i]);
    // Two passes, counting then writing each record in its place: one buffer, no copies. Each
    // destination's records in one process's order.
    std::vector<std::size_t> count(ranks, 0);
    const auto visit = [&](auto&& offer) {
        for (std::uint32_t i = 0; i < fromLower.size(); ++i) offer(fromLower, i, lowerPlanes[i]);
        for (const auto& [first, end] : own)
            for (std::uint32_t i = first; i < end; ++i) offer(p, i, planes_[i]);
    };
    visit([&](const Particles&, std::uint32_t, int plane) {
        count[below] += plane == lo;
        count[above] += plane == hi - 1;
    });
    std::vector<std::size_t> at(ranks, 0), sendBytes(ranks);
    std::size_t total = 0;
    for (int r = 0; r < ranks; ++r) {
        at[r] = total;
        sendBytes[r] = count[r] * sizeof(ParticleRecord);
        total += sendBytes[r];
    }
    std::vector<char>& send = sendBuffer_;
    send.resize(total);
    visit([&](const Particles& q, std::uint32_t i, int plane) {
        if (plane == lo) { writeRecord(q, i, send.data() + at[below]); at[below] += sizeof(ParticleRecord); }
        if (plane == hi - 1) { writeRecord(q, i, send.data() + at[above]); at[above] += sizeof(ParticleRecord); }
    });
    std::vector<std::size_t> counts;
    comm_->exchange(send, sendBytes, receiveBuffer_, counts);
    appendRecords(receiveBuffer_.data(), receiveBuffer_.size() / sizeof(ParticleRecord), p);
}

std::size_t SlabDomain::dropGhosts(Particles& p, const CellList& cells) const {
    const int hi = endPlane();
    const std::size_t begin = cells.cellStart(cells.cellIndex(firstPlane(), 0, 0));
    const std::size_t end = hi == slabs_.planes() ? cells.sortedCount() : cells.cellStart(cells.cellIndex(hi, 0, 0));
    const std::size_t own = end - begin;
    if (begin == 0 || begin > own) {
        keepRange(p, begin, end);
        return 0;
    }
    // The last `begin` own particles into the lower ghosts' places: [begin, end) keeps the rest.
    const auto fill = [&](auto& a) {
        std::copy(a.begin() + static_cast<long>(end - begin), a.begin() + static_cast<long>(end), a.begin());
        a.resize(own);
    };
    for (auto* a : {&p.rx, &p.ry, &p.rz, &p.vx, &p.vy, &p.vz, &p.fx, &p.fy, &p.fz}) fill(*a);
    fill(p.id);
    fill(p.species);
    return begin;
}

Particles SlabDomain::gather(const Particles& p) const {
    std::vector<char> mine, all;
    mine.reserve(p.size() * sizeof(ParticleRecord));
    for (std::size_t i = 0; i < p.size(); ++i) appendRecord(p, i, mine);
    std::vector<std::size_t> counts;
    comm_->gather(mine, all, counts);
    Particles out;
    appendRecords(all.data(), all.size() / sizeof(ParticleRecord), out);
    return out;
}

}  // namespace dpd
