#include "neighbour/CellList.hpp"

#include "core/Axis.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#if defined(__AVX2__)
#include <immintrin.h>
#endif

namespace dpd {

namespace {

// Whether any of the `count` positions from x, y, z on lies outside [lo, hi) along some axis. A
// position that is NaN counts as inside, as the comparisons say (the run's monitor reports it).
bool anyOutside(const double* x, const double* y, const double* z, long count, const Eigen::Vector3d& lo,
                const Eigen::Vector3d& hi) {
#if defined(__AVX2__)
    // A full block of eight in vector compares: the scalar form compiled to six compare-and-set
    // pairs per particle, half of the key pass.
    if (count == 8) {
        __m256d out = _mm256_setzero_pd();
        const double* axes[3] = {x, y, z};
        for (int a = 0; a < 3; ++a) {
            const __m256d l = _mm256_set1_pd(lo[a]), h = _mm256_set1_pd(hi[a]);
            for (int half = 0; half < 8; half += 4) {
                const __m256d v = _mm256_loadu_pd(axes[a] + half);
                out = _mm256_or_pd(out, _mm256_or_pd(_mm256_cmp_pd(v, l, _CMP_LT_OQ), _mm256_cmp_pd(v, h, _CMP_GE_OQ)));
            }
        }
        return _mm256_movemask_pd(out) != 0;
    }
#endif
    bool outside = false;
    for (long i = 0; i < count; ++i)
        outside |= (x[i] < lo.x()) | (x[i] >= hi.x()) | (y[i] < lo.y()) | (y[i] >= hi.y()) | (z[i] < lo.z()) |
                   (z[i] >= hi.z());
    return outside;
}

}  // namespace

void CellList::setup(const Box& box, double cutoff) {
    box_ = box;
    const Eigen::Vector3d L = box.length();
    for (int a = 0; a < 3; ++a) {
        if (!box.isActiveAxis(a)) {
            n_[a] = 1;
            size_[a] = L[a];
            invSize_[a] = 0.0;  // every particle in cell 0 along the inactive axis
            continue;
        }
        n_[a] = static_cast<int>(std::floor(L[a] / cutoff));
        // Two cells suffice: the stencil's offsets -1 and +1 then reach the same cell as two images,
        // of which at most one lies within the cutoff when the box is two cutoffs long.
        if (n_[a] < 2)
            throw std::invalid_argument("the box must be at least two cutoffs long along axis " +
                                        std::string(axisLetter(a)) + " (it is " + std::to_string(L[a]) + ")");
        size_[a] = L[a] / n_[a];
        invSize_[a] = 1.0 / size_[a];
    }
    // Two entries per cell, one more for the discarded particles' key (2 numCells), and the end.
    start_.assign(2 * static_cast<std::size_t>(numCells()) + 2, 0);
    setKeyWindows();
}

void CellList::setHomePlanes(std::vector<std::uint8_t> home, int ghostPlanes) {
    if (ghostPlanes < 1) throw std::invalid_argument("CellList::setHomePlanes: at least one ghost plane");
    homePlanes_ = std::move(home);
    ghostPlanes_ = ghostPlanes;
    setKeyWindows();
}

void CellList::setKeyWindows() {
    const auto nKeys = static_cast<std::uint32_t>(start_.size() - 1);
    keyWindows_.clear();
    if (homePlanes_.empty()) {
        keyWindows_.emplace_back(0, nKeys);
        return;
    }
    // A plane is keyed if a home plane lies within ghostPlanes + 1 planes below it or ghostPlanes
    // above: the home planes (the slab and the one before it) and the ghost planes after the slab
    // and before that plane hold the particles, and the plane after the last is read for where the
    // last one ends; one more plane below is keyed with them.
    const int nx = n_[0];
    const auto home = [&](int ix) { return isHomePlane(((ix % nx) + nx) % nx); };
    const auto nearHome = [&](int ix) {
        for (int d = -ghostPlanes_ - 1; d <= ghostPlanes_; ++d)
            if (home(ix + d)) return true;
        return false;
    };
    const auto keysPerPlane = static_cast<std::uint32_t>(2 * n_[1] * n_[2]);
    for (int ix = 0; ix < nx; ++ix) {
        if (!nearHome(ix)) continue;
        const std::uint32_t first = static_cast<std::uint32_t>(ix) * keysPerPlane;
        if (!keyWindows_.empty() && keyWindows_.back().second == first) keyWindows_.back().second = first + keysPerPlane;
        else keyWindows_.emplace_back(first, first + keysPerPlane);
    }
    const std::uint32_t discardKey = nKeys - 1;
    if (!keyWindows_.empty() && keyWindows_.back().second == discardKey) keyWindows_.back().second = nKeys;
    else keyWindows_.emplace_back(discardKey, nKeys);
}

void CellList::sortParticles(Particles& p, SortForces forces) {
    frozenOfSpecies_.clear();
    sort(p, forces);
}

void CellList::sortParticles(Particles& p, const std::vector<std::uint8_t>& frozenOfSpecies, SortForces forces) {
    frozenOfSpecies_ = frozenOfSpecies;
    // No frozen species: the plain sort, and the pair loop need not look for frozen parts.
    if (std::none_of(frozenOfSpecies_.begin(), frozenOfSpecies_.end(), [](std::uint8_t f) { return f != 0; }))
        frozenOfSpecies_.clear();
    sort(p, forces);
}

// The three components of a vector field moved in one pass: each step of the loop reads order_ once
// and three nearly sequential sources. Measured on the sort's own permutation at 256,000 particles:
// 1.2 ns per element against 1.8 ns for one array per pass (more streams per pass were slower again).
void CellList::gatherVector(ParticleArray<double>& x, ParticleArray<double>& y, ParticleArray<double>& z) {
    const long n = static_cast<long>(order_.size());
#pragma omp single
    for (auto& s : scratch_) s.resize(x.size());
    const std::uint32_t* __restrict order = order_.data();
    const double* __restrict xs = x.data();
    const double* __restrict ys = y.data();
    const double* __restrict zs = z.data();
    double* __restrict xd = scratch_[0].data();
    double* __restrict yd = scratch_[1].data();
    double* __restrict zd = scratch_[2].data();
#pragma omp for schedule(static)
    for (long k = 0; k < n; ++k) {
        const std::uint32_t o = order[k];
        xd[k] = xs[o]; yd[k] = ys[o]; zd[k] = zs[o];
    }
    // The implicit barrier of the loop above: every thread is done before the buffers trade places.
#pragma omp single
    { x.swap(scratch_[0]); y.swap(scratch_[1]); z.swap(scratch_[2]); }
}

void CellList::gatherIdentity(Particles& p) {
    const long n = static_cast<long>(order_.size());
#pragma omp single
    { idScratch_.resize(p.id.size()); speciesScratch_.resize(p.species.size()); }
    // Raw pointers: through the vectors, every store could alias their data pointers, which the loop
    // then reloaded for each element.
    const std::uint32_t* __restrict order = order_.data();
    const std::uint64_t* __restrict id = p.id.data();
    const std::uint8_t* __restrict species = p.species.data();
    std::uint64_t* __restrict idTo = idScratch_.data();
    std::uint8_t* __restrict speciesTo = speciesScratch_.data();
#pragma omp for schedule(static)
    for (long k = 0; k < n; ++k) {
        const std::uint32_t o = order[k];
        idTo[k] = id[o];
        speciesTo[k] = species[o];
    }
#pragma omp single
    { p.id.swap(idScratch_); p.species.swap(speciesScratch_); }
}

void CellList::sort(Particles& p, SortForces forces) {
    const long n = static_cast<long>(p.size());
    keyOf_.resize(n);
    order_.resize(n);
    // Key 2c for the mobile particles of cell c, 2c + 1 for its frozen ones.
    const bool split = splitsFrozen();
    // Positions are wrapped into the box on the way: this is their one pass before the pair loop. The
    // keys are computed eight particles at a time after their block is wrapped, so the key arithmetic
    // vectorises (a particle left the box in few blocks: the wrap's branch is rarely taken).
    double* __restrict rx = p.rx.data();
    double* __restrict ry = p.ry.data();
    double* __restrict rz = p.rz.data();
    std::uint32_t* __restrict key = keyOf_.data();
    const Eigen::Vector3d lo = box_.lo, hi = box_.hi;
    // A block's keys are bounded while they are still in the cache (SortKeyBlocks), when several
    // threads will sort.
    constexpr long kBlock = 8, kKeyBlock = SortKeyBlocks::kBlock;
    keyBlocks_.resize(static_cast<std::uint32_t>(n));
    const bool boundBlocks = omp_get_max_threads() > 1;
#pragma omp parallel for schedule(static)
    for (long s = 0; s < n; s += kKeyBlock) {
        const long sEnd = std::min(s + kKeyBlock, n);
        for (long b = s; b < sEnd; b += kBlock) {
            const long e = std::min(b + kBlock, sEnd);
            if (anyOutside(rx + b, ry + b, rz + b, e - b, lo, hi))
                for (long i = b; i < e; ++i) box_.wrapPoint(rx[i], ry[i], rz[i]);
            for (long i = b; i < e; ++i)
                key[i] = 2 * static_cast<std::uint32_t>(cellIndex(axisCell(rx[i], 0), axisCell(ry[i], 1), axisCell(rz[i], 2)));
            if (split)
                for (long i = b; i < e; ++i) key[i] += isFrozenSpecies(p.species[i]) ? 1u : 0u;
        }
        if (boundBlocks) keyBlocks_.record(static_cast<std::uint32_t>(s), key + s, static_cast<std::uint32_t>(sEnd - s));
    }
    if (!boundBlocks) keyBlocks_.coverEveryKey();
    const std::uint32_t discardKey = 2 * static_cast<std::uint32_t>(numCells());
    for (const std::uint32_t i : discarded_) {
        key[i] = discardKey;
        keyBlocks_.widen(i, discardKey);
    }
    discarded_.clear();
    countingSort();
#pragma omp parallel
    {
        gatherVector(p.rx, p.ry, p.rz);
        gatherVector(p.vx, p.vy, p.vz);
        if (forces == SortForces::Move) gatherVector(p.fx, p.fy, p.fz);
        gatherIdentity(p);
    }
}

void CellList::countingSort() {
    // Stable counting sort: particles keep their relative order inside a cell, so the layout (and
    // with it the summation order of forces) is a function of the state alone. In parallel without
    // per-thread counts: each thread owns a range of keys (of the key windows: all keys, or a rank's
    // planes), reads every key, and counts and places only its own, in particle order. The keys are
    // read where they may hold the thread's own (SortKeyBlocks: about a thread's share of them); counts
    // and places are written once. The result does not depend on the number of threads.
    const std::uint32_t n = static_cast<std::uint32_t>(keyOf_.size());
    const std::uint32_t nKeys = static_cast<std::uint32_t>(start_.size() - 1);
    const std::uint32_t* key = keyOf_.data();
    std::uint32_t* start = start_.data();
    fill_.resize(nKeys);
    std::uint32_t* fill = fill_.data();
    std::uint32_t* order = order_.data();
    const auto& visit = visit_;
    std::size_t visited = 0;
    for (const auto& [first, end] : visit) visited += end >= first && end <= n ? end - first : n + 1;
    if (!visit.empty() && visited != n) throw std::logic_error("CellList: the visit order does not cover the particles");
    std::vector<std::uint32_t> totals(static_cast<std::size_t>(omp_get_max_threads()), 0);
    std::uint32_t windowKeys = 0;
    for (const auto& [first, end] : keyWindows_) windowKeys += end - first;
    start[0] = 0;
    bool everyKeyCounted = true;
#pragma omp parallel
    {
        const std::uint32_t threads = static_cast<std::uint32_t>(omp_get_num_threads());
        const std::uint32_t t = static_cast<std::uint32_t>(omp_get_thread_num());
        // This thread's share of the windows' keys, as parts of them; no particle has a key between
        // the windows, so one range [kBegin, kEnd) still tells a particle's key is this thread's.
        const auto vBegin = static_cast<std::uint32_t>(std::uint64_t(windowKeys) * t / threads);
        const auto vEnd = static_cast<std::uint32_t>(std::uint64_t(windowKeys) * (t + 1) / threads);
        struct Part {
            std::uint32_t begin, end;
            bool opensWindow;  // begin is its window's first key
        };
        std::vector<Part> parts;
        std::uint32_t v = 0;
        for (const auto& [first, end] : keyWindows_) {
            const std::uint32_t lo = std::max(vBegin, v), hi = std::min(vEnd, v + (end - first));
            if (lo < hi) parts.push_back({first + (lo - v), first + (hi - v), lo == v});
            v += end - first;
        }
        const std::uint32_t kBegin = parts.empty() ? 0 : parts.front().begin;
        const std::uint32_t kEnd = parts.empty() ? 0 : parts.back().end;
        const std::uint32_t width = kEnd - kBegin;
        // start[k + 1]: the count of key k, then the running sum over this thread's keys up to k.
        for (const Part& part : parts) std::fill(start + part.begin + 1, start + part.end + 1, 0u);
        const SortKeyBlocks& blocks = keyBlocks_;
        blocks.forEachKeyIn(key, 0, n, kBegin, width, [&](std::uint32_t i) { ++start[key[i] + 1]; });
        std::uint32_t running = 0;
        for (const Part& part : parts)
            for (std::uint32_t k = part.begin; k < part.end; ++k) {
                running += start[k + 1];
                start[k + 1] = running;
            }
        totals[t] = running;
#pragma omp barrier
        std::uint32_t before = 0, counted = 0;  // particles of the keys below this thread's; of all
        for (std::uint32_t s = 0; s < threads; ++s) {
            if (s < t) before += totals[s];
            counted += totals[s];
        }
        // A particle whose key lies in no window was counted by nobody: nothing placed, and the
        // sort refuses below (its place would be read from cell starts left from another sort).
        const bool place = counted == n;
        if (t == 0) everyKeyCounted = place;
        std::uint32_t begin = before;
        for (const Part& part : parts) {
            if (!place) break;
            // A window's first key: its start, which no other key's end writes.
            if (part.opensWindow) start[part.begin] = begin;
            for (std::uint32_t k = part.begin; k < part.end; ++k) {
                fill[k] = begin;
                begin = start[k + 1] + before;
                start[k + 1] = begin;
            }
        }
        const auto placeOne = [&](std::uint32_t i) { order[fill[key[i]]++] = i; };
        if (place && visit.empty()) {
            blocks.forEachKeyIn(key, 0, n, kBegin, width, placeOne);
        } else if (place) {  // the ranges in the order given (setVisitOrder)
            for (const auto& [first, end] : visit) blocks.forEachKeyIn(key, first, end, kBegin, width, placeOne);
        }
    }
    visit_.clear();
    if (!everyKeyCounted) throw std::logic_error("CellList: a particle lies outside the planes this rank sorts");
}

std::size_t CellList::memoryBytes() const {
    return sizeof(std::uint32_t) * (start_.capacity() + keyOf_.capacity() + order_.capacity() + fill_.capacity()) +
           frozenOfSpecies_.capacity() +
           sizeof(double) * (scratch_[0].capacity() + scratch_[1].capacity() + scratch_[2].capacity()) +
           sizeof(std::uint64_t) * idScratch_.capacity() + speciesScratch_.capacity();
}

}  // namespace dpd
