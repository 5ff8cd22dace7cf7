#include "parallel/SlabDomain.hpp"

#include "parallel/ParticleColumns.hpp"
#include "parallel/ParticleRecord.hpp"
#include "parallel/RankChains.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#if defined(__AVX2__)
#include <immintrin.h>
#endif

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

// What goes to one rank in a migration: counts of particles, of deferred crossings and of bond
// vectors, then the three.
struct MigrationHeader {
    std::uint64_t particles = 0, deferred = 0, bondVectors = 0;
};

struct MigrationParcel {
    MigrationHeader header;
    std::vector<char> records, crossings, bondVectors;
    std::vector<char> bytes() const {
        std::vector<char> out(reinterpret_cast<const char*>(&header), reinterpret_cast<const char*>(&header) + sizeof header);
        out.insert(out.end(), records.begin(), records.end());
        out.insert(out.end(), crossings.begin(), crossings.end());
        out.insert(out.end(), bondVectors.begin(), bondVectors.end());
        return out;
    }
};

constexpr std::uint32_t kBlock = 8;

// The planes of a slab but its first and last, for a quick test of a block of particles.
struct InnerPlanes {
    double xLo, xHi, invCellSize;  // the box along x, and its cells' width
    int first, end;                // the slab's planes
    // Whether kBlock positions from x on all lie in the box and in the inner planes: the cell's
    // arithmetic of CellList::axisCell, without the clamp (a position it would clamp fails the test).
    bool holdAll(const double* x) const {
#if defined(__AVX2__)
        // In vector compares, four at a time: the compiler left the loop below scalar (3 ns a particle,
        // most of the migration's time). A truncation out of int's range gives INT_MIN: outside.
        const __m256d lo = _mm256_set1_pd(xLo), hi = _mm256_set1_pd(xHi), inv = _mm256_set1_pd(invCellSize);
        const __m128i afterFirst = _mm_set1_epi32(first + 1), beforeLast = _mm_set1_epi32(end - 2);
        __m256d outsideBox = _mm256_setzero_pd();
        __m128i outsidePlanes = _mm_setzero_si128();
        for (std::uint32_t half = 0; half < kBlock; half += 4) {
            const __m256d v = _mm256_loadu_pd(x + half);
            outsideBox = _mm256_or_pd(outsideBox, _mm256_or_pd(_mm256_cmp_pd(v, lo, _CMP_LT_OQ), _mm256_cmp_pd(v, hi, _CMP_GE_OQ)));
            const __m128i plane = _mm256_cvttpd_epi32(_mm256_mul_pd(_mm256_sub_pd(v, lo), inv));
            outsidePlanes = _mm_or_si128(outsidePlanes, _mm_or_si128(_mm_cmpgt_epi32(afterFirst, plane), _mm_cmpgt_epi32(plane, beforeLast)));
        }
        return _mm256_movemask_pd(outsideBox) == 0 && _mm_movemask_epi8(outsidePlanes) == 0;
#else
        for (std::uint32_t k = 0; k < kBlock; ++k) {
            if (!(x[k] >= xLo && x[k] < xHi)) return false;  // outside the box, or NaN: before the int conversion
            const int plane = static_cast<int>((x[k] - xLo) * invCellSize);
            if (plane <= first || plane >= end - 1) return false;
        }
        return true;
#endif
    }
};

// The plane a particle's sort will put it in (the sort wraps the position, so the same wrap here).
int planeOf(const CellList& cells, double x) { return cells.axisCell(cells.box().wrap(x, 0), 0); }

// Which of a slab's particles (planes [lo, hi)) its neighbours take as ghosts: all of the plane at
// either face (the pair loop's), and in the planes behind it, as far as a bond reaches, only those of
// the species that reach that far (the chains' beads, for the bond pass).
struct GhostSource {
    int lo, hi, planes;
    const std::uint8_t* farSpecies;
    bool below(int plane, std::uint8_t species) const { return plane == lo || (plane < lo + planes && farSpecies[species]); }
    bool above(int plane, std::uint8_t species) const { return plane == hi - 1 || (plane >= hi - planes && farSpecies[species]); }
};

}  // namespace

int SlabDomain::rankBelow() const {
    const int n = slabs_.planes();
    return slabs_.ownerOf((firstPlane() - 1 + n) % n);
}

int SlabDomain::rankAbove() const { return slabs_.ownerOf(endPlane() % slabs_.planes()); }

SlabDomain::SlabDomain(const Communicator& comm, SlabDecomposition slabs)
    : comm_(&comm), slabs_(std::move(slabs)), farGhostSpecies_(256, 0) {}

void SlabDomain::setFarGhostSpecies(const std::vector<std::uint8_t>& species) {
    farGhostSpecies_.assign(256, 0);
    std::copy(species.begin(), species.begin() + static_cast<long>(std::min<std::size_t>(species.size(), 256)),
              farGhostSpecies_.begin());
}

std::shared_ptr<SlabDomain> SlabDomain::balanced(const Communicator& comm, const CellList& cells, const Particles& p,
                                                 const std::vector<std::uint8_t>& frozenOfSpecies, int ghostPlanes) {
    std::vector<double> weights(static_cast<std::size_t>(cells.cellsPerAxis()[0]), 0.0);
    for (std::size_t i = 0; i < p.size(); ++i)
        weights[planeOf(cells, p.rx[i])] += frozenOfSpecies[p.species[i]] ? SlabDecomposition::kFrozenWeight : 1.0;
    return std::make_shared<SlabDomain>(comm, SlabDecomposition::balanced(weights, comm.size(), ghostPlanes));
}

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
                         ChainBonds* bonds, Particles& fromLower, std::vector<std::uint32_t>& leavers) const {
    const int me = comm_->rank();
    const int lo = firstPlane(), hi = endPlane();
    const int below = rankBelow(), above = rankAbove();
    // What goes down to `below` and up to `above` (with two ranks, one rank: all of it down).
    MigrationParcel parcels[2];
    std::vector<std::uint8_t> deferredLeaves(deferred.size(), 0);
    leavers.clear();
    firstPlaneOwn_.clear();
    lastPlaneOwn_.clear();
    const double* rx = p.rx.data();
    // The planes this rank's neighbours take ghosts from: the first and the last `ghosts` of the slab.
    const int ghosts = slabs_.ghostPlanes();
    const GhostSource source{lo, hi, ghosts, farGhostSpecies_.data()};
    const InnerPlanes inner{cells.box().lo.x(), cells.box().hi.x(), 1.0 / cells.cellSize().x(), lo + ghosts - 1, hi - ghosts + 1};
    for (const auto& [first, end] : own)
        for (std::uint32_t i = first; i < end; ++i) {
            // Blocks in the slab's inner planes, most of them, neither leave nor serve as ghosts.
            if (i % kBlock == 0 && i + kBlock <= end && inner.holdAll(rx + i)) {
                i += kBlock - 1;
                continue;
            }
            const int plane = planeOf(cells, rx[i]);
            if (plane >= lo && plane < hi) {
                if (source.below(plane, p.species[i])) firstPlaneOwn_.push_back(i);
                if (source.above(plane, p.species[i])) lastPlaneOwn_.push_back(i);
                continue;
            }
            const int to = slabs_.ownerOf(plane);
            if (to != below && to != above)
                throw std::runtime_error("particle " + std::to_string(p.id[i]) + " moved from the slab of rank " + std::to_string(me) +
                                         " to plane " + std::to_string(plane) + " of rank " + std::to_string(to) +
                                         ", past the neighbouring slabs, in one step: the run is unstable (is deltaT too large?)");
            MigrationParcel& parcel = parcels[to == below ? 0 : 1];
            leavers.push_back(i);
            appendRecord(p, i, parcel.records);
            ++parcel.header.particles;
            if (bonds) appendBondVectors(*bonds, p.id[i], parcel.bondVectors, parcel.header.bondVectors);
            const auto d = std::lower_bound(deferred.begin(), deferred.end(), p.id[i],
                                            [](const DeferredCrossing& c, std::uint64_t id) { return c.id < id; });
            if (d != deferred.end() && d->id == p.id[i]) {
                const std::size_t at = parcel.crossings.size();
                parcel.crossings.resize(at + sizeof(DeferredCrossing));
                std::memcpy(parcel.crossings.data() + at, &*d, sizeof(DeferredCrossing));
                deferredLeaves[static_cast<std::size_t>(d - deferred.begin())] = 1;
                ++parcel.header.deferred;
            }
        }
    std::vector<char> fromBelow, fromAbove;
    comm_->exchangeWithNeighbours(below, above, parcels[0].bytes(), parcels[1].bytes(), fromBelow, fromAbove);

    std::size_t kept = 0;
    for (std::size_t k = 0; k < deferred.size(); ++k)
        if (!deferredLeaves[k]) deferred[kept++] = deferred[k];
    deferred.resize(kept);
    fromLower = Particles();
    // In the senders' rank order, as one process holds them: those from lower ranks go before this
    // rank's own (fromLower), those from higher ranks after them.
    const auto take = [&](const std::vector<char>& bytes, int from) {
        const char* at = bytes.data();
        MigrationHeader h;
        std::memcpy(&h, at, sizeof h);
        at += sizeof h;
        appendRecords(at, h.particles, from < me ? fromLower : p);
        at += h.particles * sizeof(ParticleRecord);
        for (std::uint64_t k = 0; k < h.deferred; ++k, at += sizeof(DeferredCrossing)) {
            DeferredCrossing d;
            std::memcpy(&d, at, sizeof d);
            deferred.push_back(d);
        }
        if (h.bondVectors > 0 && !bonds) throw std::logic_error("SlabDomain::migrate: bond vectors came to a run without bonds");
        if (bonds) takeBondVectors(at, h.bondVectors, *bonds);
    };
    if (below <= above) {
        take(fromBelow, below);
        take(fromAbove, above);
    } else {
        take(fromAbove, above);
        take(fromBelow, below);
    }
    std::sort(deferred.begin(), deferred.end(), [](const DeferredCrossing& a, const DeferredCrossing& b) { return a.id < b.id; });
}

void SlabDomain::addGhosts(const Particles& fromLower, Particles& p, const Ranges& own, const CellList& cells) const {
    if (own.empty()) throw std::logic_error("SlabDomain::addGhosts: no own ranges");
    const int lo = firstPlane(), hi = endPlane();
    const int below = rankBelow(), above = rankAbove();
    // Per plane, one process's order: those from lower ranks, the slab's own (as migrate found them),
    // those from higher ranks (appended to p after `own`'s first ranges, which migrate scanned).
    ParticleRefs& firstPlane = firstPlaneRefs_;
    ParticleRefs& lastPlane = lastPlaneRefs_;
    firstPlane.clear();
    lastPlane.clear();
    const GhostSource source{lo, hi, slabs_.ghostPlanes(), farGhostSpecies_.data()};
    const auto sortIn = [&](const Particles& q, std::uint32_t i) {
        const int plane = planeOf(cells, q.rx[i]);
        if (source.below(plane, q.species[i])) firstPlane.emplace_back(&q, i);
        if (source.above(plane, q.species[i])) lastPlane.emplace_back(&q, i);
    };
    for (std::uint32_t i = 0; i < fromLower.size(); ++i) sortIn(fromLower, i);
    for (const std::uint32_t i : firstPlaneOwn_) firstPlane.emplace_back(&p, i);
    for (const std::uint32_t i : lastPlaneOwn_) lastPlane.emplace_back(&p, i);
    const auto fromHigher = own.back();  // migrate appended them: the last range
    for (std::uint32_t i = fromHigher.first; i < fromHigher.second; ++i) sortIn(p, i);
    sendBelow_.resize(columnBytes(firstPlane.size()));
    writeColumns(firstPlane, sendBelow_.data());
    sendAbove_.resize(columnBytes(lastPlane.size()));
    writeColumns(lastPlane, sendAbove_.data());
    comm_->exchangeWithNeighbours(below, above, sendBelow_, sendAbove_, receiveBelow_, receiveAbove_);
    // A block of columns from each side, each its sender's planes in one process's order; the two fill
    // planes of their own (a slab holds enough planes for that), so which comes first does not matter.
    appendColumns(receiveBelow_.data(), p);
    appendColumns(receiveAbove_.data(), p);
}

namespace {

// Particles [first, end) of the sorted arrays that lie in plane `plane` (its cells are one range).
std::pair<std::size_t, std::size_t> planeRange(const CellList& cells, int plane) {
    const int nx = cells.cellsPerAxis()[0];
    const std::size_t first = cells.cellStart(cells.cellIndex(plane, 0, 0));
    const std::size_t end = plane + 1 == nx ? cells.sortedCount() : cells.cellStart(cells.cellIndex(plane + 1, 0, 0));
    return {first, end};
}

}  // namespace

void SlabDomain::refreshGhostForces(Particles& p, const CellList& cells) const {
    const int n = slabs_.planes();
    const int lo = firstPlane(), hi = endPlane();
    const int below = rankBelow(), above = rankAbove();
    // Each plane's particles are one range of the sorted arrays: its forces go as three columns.
    const auto put = [&](std::pair<std::size_t, std::size_t> r, std::vector<char>& to) {
        const std::size_t bytes = (r.second - r.first) * sizeof(double);
        to.resize(3 * bytes);
        char* at = to.data();
        for (const auto* f : {&p.fx, &p.fy, &p.fz}) {
            std::memcpy(at, f->data() + r.first, bytes);
            at += bytes;
        }
    };
    // Down the first plane's, up the last plane's: the neighbours hold them as ghosts in the same order.
    put(planeRange(cells, lo), sendBelow_);
    put(planeRange(cells, hi - 1), sendAbove_);
    comm_->exchangeWithNeighbours(below, above, sendBelow_, sendAbove_, receiveBelow_, receiveAbove_);
    const auto take = [&](const std::vector<char>& from, std::pair<std::size_t, std::size_t> r) {
        const std::size_t bytes = (r.second - r.first) * sizeof(double);
        if (from.size() != 3 * bytes)
            throw std::logic_error("SlabDomain::refreshGhostForces: a neighbour's plane and the ghosts differ in number");
        const char* at = from.data();
        for (auto* f : {&p.fx, &p.fy, &p.fz}) {
            std::memcpy(f->data() + r.first, at, bytes);
            at += bytes;
        }
    };
    take(receiveBelow_, planeRange(cells, (lo - 1 + n) % n));  // below's last plane: the lower ghosts
    take(receiveAbove_, planeRange(cells, hi % n));            // above's first plane: the upper ghosts
}

std::pair<std::size_t, std::size_t> SlabDomain::ownRange(const CellList& cells) const {
    const int hi = endPlane();
    const std::size_t begin = cells.cellStart(cells.cellIndex(firstPlane(), 0, 0));
    const std::size_t end = hi == slabs_.planes() ? cells.sortedCount() : cells.cellStart(cells.cellIndex(hi, 0, 0));
    return {begin, end};
}

std::size_t SlabDomain::dropGhosts(Particles& p, const CellList& cells) const {
    const auto [begin, end] = ownRange(cells);
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

Particles SlabDomain::withPlaneAbove(const Particles& own, const CellList& cells) const {
    const int lo = firstPlane();
    ParticleRefs firstPlane;
    for (std::uint32_t i = 0; i < own.size(); ++i)
        if (planeOf(cells, own.rx[i]) == lo) firstPlane.emplace_back(&own, i);
    std::vector<char> send(columnBytes(firstPlane.size())), fromBelow, fromAbove;
    writeColumns(firstPlane, send.data());
    comm_->exchangeWithNeighbours(rankBelow(), rankAbove(), send, {}, fromBelow, fromAbove);
    Particles local = own;
    appendColumns(fromAbove.data(), local);
    return local;
}

Particles SlabDomain::gather(const Particles& p) const { return gatherParticles(p, false); }

Particles SlabDomain::gatherToAll(const Particles& p) const { return gatherParticles(p, true); }

Particles SlabDomain::gatherParticles(const Particles& p, bool everywhere) const {
    std::vector<char> mine, all;
    mine.reserve(p.size() * sizeof(ParticleRecord));
    for (std::size_t i = 0; i < p.size(); ++i) appendRecord(p, i, mine);
    std::vector<std::size_t> counts;
    comm_->gather(mine, all, counts);
    if (everywhere) comm_->broadcast(all);
    Particles out;
    appendRecords(all.data(), all.size() / sizeof(ParticleRecord), out);
    return out;
}

}  // namespace dpd
