// The cell list and the slab-coloured pair loop visit every pair within the cutoff exactly once,
// compared with a brute-force O(N^2) minimum-image search (neighbour/CellList.*, forces/PairForceLoop.*).
//
// Two checks per box:
//  1. A recording evaluator (same interface as DpdPairEvaluator) stores, for every call, the squared
//     distance and the pair's noise value zeta = pairUniform(step, id_i, id_j); the noise value is a
//     32-bit fingerprint of the unordered pair, so the sorted list of (zeta, r^2) records is the
//     multiset of visited pairs. It must equal the brute-force list: same length (nothing missed,
//     nothing twice), same fingerprints, same distances to the single-precision search's round-off
//     (forces/SinglePrecisionPairs.hpp).
//  2. Full DPD forces (conservative, dissipative and random terms) from the loop against the same
//     evaluator applied to the brute-force pair list, particle by particle, within what the
//     single-precision separations can do to each particle's pairs.
#include "core/Box.hpp"
#include "core/Particles.hpp"
#include "core/Species.hpp"
#include "forces/DpdPairForce.hpp"
#include "forces/PairForceLoop.hpp"
#include "neighbour/CellList.hpp"
#include "neighbour/SortKeyBlocks.hpp"
#include "random/PairRandom.hpp"
#include "../forces/SinglePrecisionPairs.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <tuple>
#include <vector>

using namespace dpd;

namespace {

struct PairRecord {
    double zeta;
    double r2;
    bool operator<(const PairRecord& o) const { return std::tie(zeta, r2) < std::tie(o.zeta, o.r2); }
};

// Records every pair the loop evaluates, one list per thread (the loop runs in parallel).
struct RecordingEvaluator {
    std::vector<std::vector<PairRecord>>* perThread;
    inline double forceOverR(double r2, double /*rDotV*/, const PairCoeffs& /*c*/, double zeta) const {
        (*perThread)[omp_get_thread_num()].push_back({zeta, r2});
        return 0.0;
    }
};

// Random particles in a box (uniform, ids in a shuffled order so that cell sorting really permutes),
// plus a few on the faces: exactly at lo, and just below hi.
Particles randomParticles(const Box& box, double density, std::uint64_t seed) {
    const PairRandom rng(seed);
    const std::size_t n = static_cast<std::size_t>(std::llround(density * box.volume()));
    Particles p;
    for (std::size_t k = 0; k < n; ++k) {
        const auto u = rng.particleUniforms(0, k, kStreamInitialPosition);
        const auto g = rng.particleGaussians(0, k, kStreamInitialVelocity);
        Eigen::Vector3d r;
        for (int a = 0; a < 3; ++a) r[a] = box.lo[a] + u[a] * box.length()[a];
        if (box.dimension == 2) r.y() = 0.5 * (box.lo.y() + box.hi.y());
        p.add((k * 7919) % 1000003 + 5, 0, r.x(), r.y(), r.z(), g[0], box.dimension == 3 ? g[1] : 0.0, g[2]);
    }
    // Particles on the faces of the box and in its corner: one exactly at lo, one a rounding step below
    // hi and shifted by 0.37 along the other active axes (so the two are 0.37 or 0.52 apart across the
    // periodic boundary, never on top of each other).
    std::uint64_t extraId = 2000000;
    for (int a = 0; a < 3; ++a) {
        if (!box.isActiveAxis(a)) continue;
        Eigen::Vector3d r = 0.5 * (box.lo + box.hi);
        r[a] = box.lo[a];
        p.add(extraId++, 0, r.x(), r.y(), r.z());
        for (int b = 0; b < 3; ++b)
            if (b != a && box.isActiveAxis(b)) r[b] += 0.37;
        r[a] = std::nextafter(box.hi[a], box.lo[a]);
        p.add(extraId++, 0, r.x(), r.y(), r.z());
    }
    const Eigen::Vector3d corner = box.dimension == 3 ? box.lo : Eigen::Vector3d(box.lo.x(), 0.5 * (box.lo.y() + box.hi.y()), box.lo.z());
    p.add(extraId++, 0, corner.x(), corner.y(), corner.z());
    return p;
}

// The loop visited exactly the expected pairs: the same multiset of (noise fingerprint, distance).
void expectSamePairs(std::vector<PairRecord> visited, std::vector<PairRecord> expected, double r2Tolerance) {
    std::sort(visited.begin(), visited.end());
    std::sort(expected.begin(), expected.end());
    ASSERT_EQ(visited.size(), expected.size()) << "pairs visited by the loop vs brute force";
    for (std::size_t k = 0; k < expected.size(); ++k) {
        ASSERT_EQ(visited[k].zeta, expected[k].zeta) << "pair " << k;
        ASSERT_NEAR(visited[k].r2, expected[k].r2, r2Tolerance) << "pair " << k;
    }
}

struct BrutePair {
    std::size_t i, j;
    Eigen::Vector3d rij;  // minimum image r_i - r_j
};

// Pairs closer than the cutoff; `nearestToCutoff` (if given) receives the smallest |r^2 - cutoff^2| of
// all pairs, inside or out.
std::vector<BrutePair> bruteForcePairs(const Particles& p, const Box& box, double cutoff, double* nearestToCutoff = nullptr) {
    std::vector<BrutePair> out;
    double nearest = INFINITY;
    const Eigen::Vector3d L = box.length();
    for (std::size_t i = 0; i < p.size(); ++i)
        for (std::size_t j = i + 1; j < p.size(); ++j) {
            Eigen::Vector3d d(p.rx[i] - p.rx[j], p.ry[i] - p.ry[j], p.rz[i] - p.rz[j]);
            for (int a = 0; a < 3; ++a)
                if (box.isActiveAxis(a)) d[a] -= L[a] * std::round(d[a] / L[a]);
                else d[a] = 0.0;
            nearest = std::min(nearest, std::abs(d.squaredNorm() - cutoff * cutoff));
            if (d.squaredNorm() < cutoff * cutoff) out.push_back({i, j, d});
        }
    if (nearestToCutoff) *nearestToCutoff = nearest;
    return out;
}

struct Case {
    const char* name;
    int dimension;
    Eigen::Vector3d lo, hi;
    double cutoff;
};

void checkCaseOnThreads(const Case& cs) {
    SCOPED_TRACE(cs.name);
    Box box;
    box.dimension = cs.dimension;
    box.lo = cs.lo;
    box.hi = cs.hi;
    Particles p = randomParticles(box, 3.0 / std::pow(cs.cutoff, cs.dimension), 31 + cs.dimension);
    CellList cells;
    cells.setup(box, cs.cutoff);
    const auto n = cells.cellsPerAxis();
    for (int a = 0; a < 3; ++a) {
        if (!box.isActiveAxis(a)) { EXPECT_EQ(n[a], 1); continue; }
        EXPECT_EQ(n[a], static_cast<int>(std::floor(box.length()[a] / cs.cutoff)));
        EXPECT_GE(cells.cellSize()[a], cs.cutoff);
    }
    cells.sortParticles(p);

    // The sort keeps every particle (a permutation of the ids) and puts each in the cell that holds it.
    ASSERT_EQ(cells.cellStart(cells.numCells()), p.size());
    for (int c = 0; c < cells.numCells(); ++c) {
        const int ix = c / (n[1] * n[2]), iy = (c / n[2]) % n[1], iz = c % n[2];
        const int idx[3] = {ix, iy, iz};
        for (std::uint32_t k = cells.cellStart(c); k < cells.cellStart(c + 1); ++k) {
            const double r[3] = {p.rx[k], p.ry[k], p.rz[k]};
            for (int a = 0; a < 3; ++a) {
                if (!box.isActiveAxis(a)) continue;
                const double lower = box.lo[a] + idx[a] * cells.cellSize()[a];
                const double upper = box.lo[a] + (idx[a] + 1) * cells.cellSize()[a];
                EXPECT_GE(r[a], lower - 1e-12 * box.length()[a]);
                EXPECT_LE(r[a], upper + 1e-12 * box.length()[a]);
            }
        }
    }

    const PairRandom random(4242);
    PairTable table(1);
    table.set(0, 0, {25.0, 4.5, 3.0, true});
    const std::uint64_t step = 17;
    const PairLoopContext ctx{cells, table, random, step};

    // 1. The visited pairs.
    std::vector<std::vector<PairRecord>> perThread(omp_get_max_threads());
    accumulatePairForces(p, ctx, RecordingEvaluator{&perThread}, cs.cutoff);
    std::vector<PairRecord> visited;
    for (const auto& v : perThread) visited.insert(visited.end(), v.begin(), v.end());
    double nearest = 0.0;
    const std::vector<BrutePair> brute = bruteForcePairs(p, box, cs.cutoff, &nearest);
    const double cellSize = cells.cellSize().maxCoeff();
    const double r2Tolerance = test::squaredDistanceError(cellSize, cs.cutoff);
    // A pair within round-off of the cutoff could fall either way; the fixed seed has none.
    ASSERT_GT(nearest, r2Tolerance);
    std::vector<PairRecord> expected;
    for (const auto& b : brute) expected.push_back({random.pairUniform(step, p.id[b.i], p.id[b.j]), b.rij.squaredNorm()});
    ASSERT_GT(expected.size(), 100u);  // the boxes hold enough pairs for the check to mean something
    expectSamePairs(visited, expected, r2Tolerance);
    if (::testing::Test::HasFatalFailure()) return;

    // 2. Full DPD forces against the brute-force sum of the same evaluator.
    PairForceParameters params;
    params.cutoff = cs.cutoff;
    params.dt = 0.04;
    const DpdPairEvaluator<true, true> eval(params);
    p.clearForces();
    accumulatePairForces(p, ctx, eval, cs.cutoff);
    std::vector<Eigen::Vector3d> f(p.size(), Eigen::Vector3d::Zero());
    std::vector<double> tolerance;
    tolerance.assign(p.size(), 1e-12);  // (constructed empty: GCC 12 warns falsely about the sized constructor here)
    for (const auto& b : brute) {
        const Eigen::Vector3d dv(p.vx[b.i] - p.vx[b.j], p.vy[b.i] - p.vy[b.j], p.vz[b.i] - p.vz[b.j]);
        const double zeta = random.pairUniform(step, p.id[b.i], p.id[b.j]);
        const double s = eval.forceOverR(b.rij.squaredNorm(), b.rij.dot(dv), table(0, 0), zeta);
        f[b.i] += s * b.rij;
        f[b.j] -= s * b.rij;
        const double error = test::pairForceError(eval, b.rij, dv, table(0, 0), zeta, test::separationComponentError(cellSize));
        tolerance[b.i] += error;
        tolerance[b.j] += error;
    }
    // Each particle's force within what its pairs' single-precision separations allow (typically
    // 1e-4 to 1e-3 of forces of order 10-100); a missing or doubled pair would be off by order 1-10.
    // The budget comes from the evaluator under test, so it is itself held to a fixed cap: 0.02
    // (measured at most 0.0084 over the cases).
    const double widest = *std::max_element(tolerance.begin(), tolerance.end());
    ASSERT_LT(widest, 0.02) << "the widest particle's budget";
    for (std::size_t i = 0; i < p.size(); ++i) {
        EXPECT_NEAR(p.fx[i], f[i].x(), tolerance[i]) << "particle id " << p.id[i];
        EXPECT_NEAR(p.fy[i], f[i].y(), tolerance[i]) << "particle id " << p.id[i];
        EXPECT_NEAR(p.fz[i], f[i].z(), tolerance[i]) << "particle id " << p.id[i];
    }
}

// On one thread and on two (ctest runs each test with one OpenMP thread; the slab colouring only
// matters with more).
void checkCase(const Case& cs) {
    const int saved = omp_get_max_threads();
    for (int threads : {1, 2}) {
        SCOPED_TRACE(threads == 1 ? "1 thread" : "2 threads");
        omp_set_num_threads(threads);
        checkCaseOnThreads(cs);
    }
    omp_set_num_threads(saved);
}

}  // namespace

TEST(CellList, PairsMatchBruteForce3DMinimumCells) {
    // 3 cells along x (the minimum) and y, 5 along z; lengths not multiples of the cutoff.
    checkCase({"3x3x5 cells", 3, Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(3.4, 3.7, 5.5), 1.0});
}

TEST(CellList, PairsMatchBruteForce3DOddAndEvenCounts) {
    // 7 x 4 x 6 cells, a box not at the origin.
    checkCase({"7x4x6 cells", 3, Eigen::Vector3d(-2.3, 1.1, 0.5), Eigen::Vector3d(5.05, 5.35, 6.9), 1.0});
    // A cutoff other than 1: floor(L / 0.8) gives 4 x 3 x 3 cells of 0.8625 x 0.833 x 0.87.
    checkCase({"cutoff 0.8", 3, Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(3.45, 2.5, 2.61), 0.8});
}

TEST(CellList, PairsMatchBruteForceFarFromTheOrigin) {
    // Coordinates in the thousands: as absolute floats they would keep only ~1e-4 (an ulp of 4096 is
    // 2.4e-4), far outside the tolerances; the search's cell-local positions keep ~1e-7 anywhere.
    checkCase({"far from the origin", 3, Eigen::Vector3d(1000.0, -3000.0, 5000.0),
               Eigen::Vector3d(1005.3, -2995.6, 5004.9), 1.0});
}

TEST(CellList, PairsMatchBruteForce2D) {
    // 2-D (x-z plane): 3 x 4 cells, then 9 x 3 cells.
    checkCase({"2-D 3x4 cells", 2, Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(3.5, 1.0, 4.4), 1.0});
    checkCase({"2-D 9x3 cells", 2, Eigen::Vector3d(1.0, -0.5, -3.0), Eigen::Vector3d(10.7, 0.5, 0.2), 1.0});
}

TEST(CellList, PairsMatchBruteForceWithTwoCellsAlongAnAxis) {
    // Two cells along an axis: the stencil reaches the other cell through both its images (offsets -1
    // and +1), each pair within the cutoff through one of them only. A thin periodic slab (scene 6 of
    // docs/scenes.md is 2 cutoffs thick), then two cells along x and z, along all three axes, in 2-D,
    // and a box of exactly two cutoffs.
    checkCase({"4x2x5 cells", 3, Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(4.3, 2.4, 5.5), 1.0});
    checkCase({"2x3x2 cells", 3, Eigen::Vector3d(-1.0, 0.5, 2.0), Eigen::Vector3d(1.5, 4.1, 4.2), 1.0});
    checkCase({"2x2x2 cells", 3, Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(2.7, 2.3, 2.9), 1.0});
    checkCase({"2-D 2x5 cells", 2, Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(2.5, 1.0, 5.4), 1.0});
    checkCase({"4x2x4 cells of exactly one cutoff along y", 3, Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(4.5, 2.0, 4.7),
               1.0});
}

TEST(CellList, SetupThrowsForBoxesShorterThanTwoCutoffs) {
    CellList cells;
    Box box;
    box.lo = Eigen::Vector3d(0, 0, 0);
    box.hi = Eigen::Vector3d(1.99, 5, 5);
    EXPECT_THROW(cells.setup(box, 1.0), std::invalid_argument);
    box.hi = Eigen::Vector3d(5, 1.99, 5);
    EXPECT_THROW(cells.setup(box, 1.0), std::invalid_argument);
    box.hi = Eigen::Vector3d(5, 5, 1.99);
    EXPECT_THROW(cells.setup(box, 1.0), std::invalid_argument);
    box.hi = Eigen::Vector3d(5, 5, 5);
    EXPECT_THROW(cells.setup(box, 2.6), std::invalid_argument);  // 5 / 2.6 < 2
    EXPECT_NO_THROW(cells.setup(box, 2.5));
    box.hi = Eigen::Vector3d(2, 2, 2);
    EXPECT_NO_THROW(cells.setup(box, 1.0));  // exactly two cutoffs is allowed
    EXPECT_EQ(cells.cellsPerAxis()[1], 2);
    // 2-D: y is inactive and may be thin; x and z still need two cutoffs.
    box.dimension = 2;
    box.hi = Eigen::Vector3d(5, 0.1, 5);
    EXPECT_NO_THROW(cells.setup(box, 1.0));
    EXPECT_EQ(cells.cellsPerAxis()[1], 1);
    box.hi = Eigen::Vector3d(5, 1, 1.5);
    EXPECT_THROW(cells.setup(box, 1.0), std::invalid_argument);
    box.hi = Eigen::Vector3d(1.5, 1, 5);
    EXPECT_THROW(cells.setup(box, 1.0), std::invalid_argument);
}

// Frozen particles and species that differ. Three species: 0 mobile, 1 frozen, 2 frozen. The pairs of
// frozen species are non-interacting, as System makes them; with `extraNonInteracting` the pair
// (0, 2) is non-interacting too, which the layout cannot skip, so the loop must look the species up.
// The coefficients differ between pairs, so the loop takes them per pair. On one thread and on two:
//  - the sort puts every cell's mobile particles before its frozen ones;
//  - the visited pairs are exactly the brute-force pairs that interact (frozen-frozen ones never
//    reach the evaluator);
//  - the forces equal the brute-force sum with each pair's own coefficients.
namespace {

void checkMixedSpecies(bool extraNonInteracting) {
    Box box;
    box.lo = Eigen::Vector3d(0, 0, 0);
    box.hi = Eigen::Vector3d(6.3, 4.2, 5.5);
    Particles p = randomParticles(box, 3.0, 77);
    // Frozen species in blocks of space (a wall-like slab at low z) and scattered by id.
    for (std::size_t k = 0; k < p.size(); ++k)
        p.species[k] = p.rz[k] < 1.5 ? 1 : (p.id[k] % 5 == 0 ? 2 : 0);
    const std::vector<std::uint8_t> frozen{0, 1, 1};
    PairTable table(3);
    table.set(0, 0, {25.0, 4.5, 3.0, true});
    table.set(0, 1, {30.0, 6.0, 3.5, true});
    table.set(0, 2, {10.0, 2.0, 2.0, !extraNonInteracting});
    table.set(1, 1, {25.0, 4.5, 3.0, false});
    table.set(1, 2, {25.0, 4.5, 3.0, false});
    table.set(2, 2, {25.0, 4.5, 3.0, false});
    const PairRandom random(99);
    const std::uint64_t step = 3;
    PairForceParameters params;
    params.dt = 0.04;
    const DpdPairEvaluator<true, true> eval(params);

    const int saved = omp_get_max_threads();
    for (int threads : {1, 2}) {
        SCOPED_TRACE(threads == 1 ? "1 thread" : "2 threads");
        omp_set_num_threads(threads);
        Particles q = p;
        CellList cells;
        cells.setup(box, 1.0);
        cells.sortParticles(q, frozen);
        ASSERT_TRUE(cells.splitsFrozen());
        for (int c = 0; c < cells.numCells(); ++c) {
            ASSERT_LE(cells.cellStart(c), cells.mobileEnd(c));
            ASSERT_LE(cells.mobileEnd(c), cells.cellStart(c + 1));
            for (std::uint32_t k = cells.cellStart(c); k < cells.cellStart(c + 1); ++k)
                ASSERT_EQ(frozen[q.species[k]] != 0, k >= cells.mobileEnd(c)) << "cell " << c;
        }
        const PairLoopContext ctx{cells, table, random, step};
        std::vector<std::vector<PairRecord>> perThread(omp_get_max_threads());
        accumulatePairForces(q, ctx, RecordingEvaluator{&perThread}, 1.0);
        std::vector<PairRecord> visited;
        for (const auto& v : perThread) visited.insert(visited.end(), v.begin(), v.end());
        std::vector<PairRecord> expected;
        std::vector<Eigen::Vector3d> f(q.size(), Eigen::Vector3d::Zero());
        std::vector<double> tolerance;
        tolerance.assign(q.size(), 1e-12);
        const double delta = test::separationComponentError(cells.cellSize().maxCoeff());
        long frozenPairs = 0;
        double nearest = 0.0;
        const std::vector<BrutePair> brute = bruteForcePairs(q, box, 1.0, &nearest);
        const double r2Tolerance = test::squaredDistanceError(cells.cellSize().maxCoeff(), 1.0);
        ASSERT_GT(nearest, r2Tolerance);
        for (const auto& b : brute) {
            const PairCoeffs& c = table(q.species[b.i], q.species[b.j]);
            frozenPairs += frozen[q.species[b.i]] && frozen[q.species[b.j]];
            if (!c.interact) continue;
            const double zeta = random.pairUniform(step, q.id[b.i], q.id[b.j]);
            expected.push_back({zeta, b.rij.squaredNorm()});
            const Eigen::Vector3d dv(q.vx[b.i] - q.vx[b.j], q.vy[b.i] - q.vy[b.j], q.vz[b.i] - q.vz[b.j]);
            const double s = eval.forceOverR(b.rij.squaredNorm(), b.rij.dot(dv), c, zeta);
            f[b.i] += s * b.rij;
            f[b.j] -= s * b.rij;
            const double error = test::pairForceError(eval, b.rij, dv, c, zeta, delta);
            tolerance[b.i] += error;
            tolerance[b.j] += error;
        }
        ASSERT_GT(frozenPairs, 100) << "the box must hold frozen-frozen pairs for the test to mean much";
        expectSamePairs(visited, expected, r2Tolerance);
        if (::testing::Test::HasFatalFailure()) break;
        q.clearForces();
        accumulatePairForces(q, ctx, eval, 1.0);
        // Tolerance as in checkCaseOnThreads, and capped likewise: it comes from the evaluator under
        // test (measured at most 0.0039 over both cases and thread counts).
        const double widest = *std::max_element(tolerance.begin(), tolerance.end());
        ASSERT_LT(widest, 0.02) << "the widest particle's budget";
        for (std::size_t i = 0; i < q.size(); ++i) {
            EXPECT_NEAR(q.fx[i], f[i].x(), tolerance[i]) << "particle id " << q.id[i];
            EXPECT_NEAR(q.fy[i], f[i].y(), tolerance[i]) << "particle id " << q.id[i];
            EXPECT_NEAR(q.fz[i], f[i].z(), tolerance[i]) << "particle id " << q.id[i];
        }
    }
    omp_set_num_threads(saved);
}

}  // namespace

TEST(CellList, FrozenPairsAreNeverVisitedAndPerPairCoefficientsAreUsed) { checkMixedSpecies(false); }

TEST(CellList, NonInteractingMobilePairsAreFilteredBySpecies) { checkMixedSpecies(true); }

namespace {

// Records (r^2, r.v, zeta) of every pair; kRandom / kVelocity are what it declares it needs.
template <bool kRandom, bool kVelocity>
struct DeclaringEvaluator {
    static constexpr bool kUsesRandom = kRandom;
    static constexpr bool kUsesVelocity = kVelocity;
    std::vector<std::vector<std::tuple<double, double, double>>>* perThread;
    inline double forceOverR(double r2, double rDotV, const PairCoeffs& /*c*/, double zeta) const {
        (*perThread)[omp_get_thread_num()].emplace_back(r2, rDotV, zeta);
        return 0.0;
    }
};

template <class Evaluator>
std::vector<std::tuple<double, double, double>> recordedPairs(Particles& p, const PairLoopContext& ctx, double cutoff) {
    std::vector<std::vector<std::tuple<double, double, double>>> perThread(omp_get_max_threads());
    accumulatePairForces(p, ctx, Evaluator{&perThread}, cutoff);
    std::vector<std::tuple<double, double, double>> all;
    for (const auto& v : perThread) all.insert(all.end(), v.begin(), v.end());
    std::sort(all.begin(), all.end());
    return all;
}

}  // namespace

namespace {

// Random particles at rho 3 in a 4.3 x 3.6 x 5.2 box, sorted by a cell list for cutoff 1; one species
// with a = 25, gamma = 4.5, sigma = 3.
struct SortedFluid {
    Particles p;
    CellList cells;
    PairTable table{1};
};

Box fluidBox() {
    Box box;
    box.lo = Eigen::Vector3d(0, 0, 0);
    box.hi = Eigen::Vector3d(4.3, 3.6, 5.2);
    return box;
}

SortedFluid sortedFluid(std::uint64_t seed) {
    const Box box = fluidBox();
    SortedFluid f{randomParticles(box, 3.0, seed), {}, PairTable(1)};
    f.cells.setup(box, 1.0);
    f.cells.sortParticles(f.p);
    f.table.set(0, 0, {25.0, 4.5, 3.0, true});
    return f;
}

}  // namespace

static_assert(EvaluatorUsesRandom<RecordingEvaluator>::value, "an evaluator that declares nothing gets zeta");
static_assert(EvaluatorUsesVelocity<RecordingEvaluator>::value, "an evaluator that declares nothing gets r.v");
static_assert(!EvaluatorUsesRandom<DeclaringEvaluator<false, true>>::value, "");
static_assert(!EvaluatorUsesVelocity<DeclaringEvaluator<true, false>>::value, "");

TEST(CellList, EvaluatorsThatNeedNoNoiseOrVelocityGetZerosForTheSamePairs) {
    // The conservative-only and dissipative-only evaluators of the split integrators declare that they
    // use no random number (and the conservative one no velocity): the loop must then pass exact zeros
    // instead, and visit the very same pairs with the same r^2 (and r.v where it is still used).
    SortedFluid f = sortedFluid(7);
    Particles& p = f.p;
    const PairRandom random(99);
    const PairLoopContext ctx{f.cells, f.table, random, 5};

    const auto full = recordedPairs<DeclaringEvaluator<true, true>>(p, ctx, 1.0);
    const auto noNoise = recordedPairs<DeclaringEvaluator<false, true>>(p, ctx, 1.0);
    const auto neither = recordedPairs<DeclaringEvaluator<false, false>>(p, ctx, 1.0);
    ASSERT_GT(full.size(), 100u);
    ASSERT_EQ(noNoise.size(), full.size());
    ASSERT_EQ(neither.size(), full.size());
    // The full evaluator really sees noise and velocities (so the zeros below are not trivially true).
    EXPECT_TRUE(std::any_of(full.begin(), full.end(), [](const auto& t) { return std::get<2>(t) != 0.0; }));
    EXPECT_TRUE(std::any_of(full.begin(), full.end(), [](const auto& t) { return std::get<1>(t) != 0.0; }));
    // Sorted by (r^2, r.v, zeta): the pairs line up one to one (their r^2 are distinct in this sample).
    for (std::size_t k = 0; k < full.size(); ++k) {
        EXPECT_EQ(std::get<0>(noNoise[k]), std::get<0>(full[k]));
        EXPECT_EQ(std::get<1>(noNoise[k]), std::get<1>(full[k]));
        EXPECT_EQ(std::get<2>(noNoise[k]), 0.0);
        EXPECT_EQ(std::get<0>(neither[k]), std::get<0>(full[k]));
        EXPECT_EQ(std::get<1>(neither[k]), 0.0);
        EXPECT_EQ(std::get<2>(neither[k]), 0.0);
    }
}

TEST(CellList, ReplacingForcesWritesThePairForcesOverWhatTheParticlesHeld) {
    // With replaceForces the loop's result is p.f = pair forces whatever p.f held; without it the pair
    // forces are added. Same pairs, same order, so both are exact: replace(stale) == add(zero), and
    // add(stale) - stale differs from them only by the rounding of the additions.
    SortedFluid f = sortedFluid(11);
    Particles& p = f.p;
    const PairRandom random(7);
    PairForceParameters params;
    params.dt = 0.04;
    const DpdPairEvaluator<true, true> eval(params);
    const std::size_t n = p.size();
    PairLoopContext ctx{f.cells, f.table, random, 3};

    p.clearForces();
    accumulatePairForces(p, ctx, eval, 1.0);
    const ParticleArray<double> added = p.fx;
    for (std::size_t k = 0; k < n; ++k) { p.fx[k] = 1e3 + k; p.fy[k] = -7.0; p.fz[k] = 0.5; }
    ctx.replaceForces = true;
    accumulatePairForces(p, ctx, eval, 1.0);
    for (std::size_t k = 0; k < n; ++k) ASSERT_EQ(p.fx[k], added[k]) << "particle " << k;
    ctx.replaceForces = false;
    for (std::size_t k = 0; k < n; ++k) p.fx[k] = 1e3 + k;
    accumulatePairForces(p, ctx, eval, 1.0);
    // Without replacing, what p.f held stays in: ~1e3 off, far beyond the rounding of ~13 additions at 1e3 (~3e-12).
    for (std::size_t k = 0; k < n; ++k) ASSERT_NEAR(p.fx[k] - (1e3 + k), added[k], 1e-9) << "particle " << k;
}

namespace {

// The same random particles, with forces of a fluid's size (|f| < 25) that tell them apart (a function
// of the id), sorted twice: with the forces moved, and with the forces left behind.
struct SortedBothWays {
    Particles before, moved, left;
    CellList movedCells, leftCells;
};

SortedBothWays sortedBothWays(std::uint64_t seed) {
    SortedBothWays s;
    const Box box = fluidBox();
    s.before = randomParticles(box, 3.0, seed);
    for (std::size_t k = 0; k < s.before.size(); ++k) {
        const double id = static_cast<double>(s.before.id[k]);
        s.before.fx[k] = std::fmod(0.618 * id, 50.0) - 25.0;
        s.before.fy[k] = std::fmod(0.414 * id, 50.0) - 25.0;
        s.before.fz[k] = std::fmod(0.732 * id, 50.0) - 25.0;
    }
    s.moved = s.before;
    s.left = s.before;
    s.movedCells.setup(box, 1.0);
    s.leftCells.setup(box, 1.0);
    s.movedCells.sortParticles(s.moved, SortForces::Move);
    s.leftCells.sortParticles(s.left, SortForces::Leave);
    return s;
}

// How many particles the sort took from another place (a test of the order means something only if many).
std::size_t displaced(const ParticleArray<std::uint32_t>& order) {
    std::size_t count = 0;
    for (std::size_t k = 0; k < order.size(); ++k) count += order[k] != k;
    return count;
}

}  // namespace

TEST(CellList, ASortThatLeavesTheForcesBehindMovesAllElseAndItsOrderFindsThem) {
    const SortedBothWays s = sortedBothWays(21);
    const Particles &moved = s.moved, &left = s.left, &before = s.before;
    ASSERT_EQ(left.id, moved.id);
    EXPECT_EQ(left.rx, moved.rx); EXPECT_EQ(left.vy, moved.vy); EXPECT_EQ(left.species, moved.species);
    // The forces stayed where they were; the order finds each particle's own.
    EXPECT_EQ(left.fx, before.fx); EXPECT_EQ(left.fz, before.fz);
    const ParticleArray<std::uint32_t>& order = s.leftCells.order();
    ASSERT_EQ(order.size(), left.size());
    for (std::size_t k = 0; k < left.size(); ++k) {
        ASSERT_EQ(left.fx[order[k]], moved.fx[k]) << "particle " << k;
        ASSERT_EQ(left.fy[order[k]], moved.fy[k]) << "particle " << k;
        ASSERT_EQ(left.fz[order[k]], moved.fz[k]) << "particle " << k;
    }
    EXPECT_GT(displaced(order), left.size() / 2);
}

TEST(CellList, APredictorReadsForcesLeftBehindThroughTheSortsOrder) {
    // Groot and Warren's predictor v + shift f with the forces the sort moved, and with the forces it
    // left behind read through its order: the same velocities, so the same pair forces to the bit.
    SortedBothWays s = sortedBothWays(23);
    Particles &moved = s.moved, &left = s.left;
    PairTable table(1);
    table.set(0, 0, {25.0, 4.5, 3.0, true});
    const PairRandom random(5);
    PairForceParameters params;
    params.dt = 0.04;
    const DpdPairEvaluator<true, true> eval(params);
    const double shift = 0.15;
    const PairLoopContext ctxMoved{s.movedCells, table, random, 2, {shift, nullptr, nullptr}, true};
    const PairLoopContext ctxLeft{s.leftCells, table, random, 2, {shift, nullptr, s.leftCells.order().data()}, true};
    accumulatePairForces(moved, ctxMoved, eval, 1.0);
    accumulatePairForces(left, ctxLeft, eval, 1.0);
    for (std::size_t k = 0; k < moved.size(); ++k) {
        ASSERT_EQ(left.fx[k], moved.fx[k]) << "particle " << k;
        ASSERT_EQ(left.fy[k], moved.fy[k]) << "particle " << k;
        ASSERT_EQ(left.fz[k], moved.fz[k]) << "particle " << k;
    }
    EXPECT_GT(displaced(s.leftCells.order()), left.size() / 2);
}

TEST(CellList, TheSortWrapsParticlesThatLeftTheBox) {
    // 8 x 5 + 3 particles (five full blocks of the key pass and a tail), each moved out of the box
    // across one face or none: the sort must bring every one back to its periodic image in the box,
    // whichever block it is in and whichever axis it left along.
    Box box;
    box.lo = Eigen::Vector3d(-1.5, 0.0, 2.0);
    box.hi = Eigen::Vector3d(2.5, 3.5, 6.0);
    const Eigen::Vector3d L = box.length();
    Particles p;
    std::map<std::uint64_t, Eigen::Vector3d> inside;  // each particle's position in the box, by id
    const int n = 43;
    for (int k = 0; k < n; ++k) {
        const Eigen::Vector3d r(box.lo.x() + L.x() * (k + 0.5) / n, box.lo.y() + L.y() * ((7 * k) % n + 0.5) / n,
                                box.lo.z() + L.z() * ((11 * k) % n + 0.5) / n);
        inside[k] = r;
        Eigen::Vector3d moved = r;
        // Particle k leaves along axis (k / 2) % 3, below for even k and above for odd, one block in
        // seven not at all (a block with nobody outside must be left alone too).
        if ((k / 8) % 7 != 3) moved[(k / 2) % 3] += (k % 2 == 0 ? -L[(k / 2) % 3] : L[(k / 2) % 3]);
        p.add(k, 0, moved.x(), moved.y(), moved.z(), 0.0, 0.0, 0.0);
    }
    CellList cells;
    cells.setup(box, 1.0);
    cells.sortParticles(p);
    ASSERT_EQ(p.size(), static_cast<std::size_t>(n));
    for (std::size_t k = 0; k < p.size(); ++k) {
        const Eigen::Vector3d& r = inside.at(p.id[k]);
        EXPECT_NEAR(p.rx[k], r.x(), 1e-12) << "id " << p.id[k];
        EXPECT_NEAR(p.ry[k], r.y(), 1e-12) << "id " << p.id[k];
        EXPECT_NEAR(p.rz[k], r.z(), 1e-12) << "id " << p.id[k];
    }
}

TEST(CellList, TheSortTakesTheArraysInTheGivenVisitOrderAndDropsTheDiscarded) {
    // Six particles in one cell and one in another; the sort is told to take indices 4-5 first, then
    // 0-3, and to discard index 1 (a decomposed run's order of storage against one process's order,
    // and a particle that left for another rank). In the cell the stable order is the visit order:
    // ids 14, 15, 10, 12, 13; the other cell holds id 16; the discarded one lies past the last cell.
    Box box;
    box.lo = Eigen::Vector3d(0, 0, 0);
    box.hi = Eigen::Vector3d(4, 4, 4);
    Particles p;
    for (int k = 0; k < 6; ++k) p.add(10 + k, 0, 0.5 + 0.05 * k, 0.5, 0.5);
    p.add(16, 0, 2.5, 2.5, 2.5);
    CellList cells;
    cells.setup(box, 1.0);
    cells.setVisitOrder({{4, 7}, {0, 4}});
    cells.setDiscarded({1});
    cells.sortParticles(p);
    ASSERT_EQ(cells.sortedCount(), 6u);
    const int home = cells.cellIndex(0, 0, 0);
    ASSERT_EQ(cells.cellStart(home + 1) - cells.cellStart(home), 5u);
    const std::uint64_t expected[5] = {14, 15, 10, 12, 13};
    for (int k = 0; k < 5; ++k) EXPECT_EQ(p.id[cells.cellStart(home) + k], expected[k]) << k;
    const int other = cells.cellIndex(2, 2, 2);
    ASSERT_EQ(cells.cellStart(other + 1) - cells.cellStart(other), 1u);
    EXPECT_EQ(p.id[cells.cellStart(other)], 16u);
    EXPECT_EQ(p.id[6], 11u);  // discarded: after every cell

    // The next sort takes the arrays in order again, and a visit order that misses particles is refused.
    p.shorten(6, false);
    cells.sortParticles(p);
    EXPECT_EQ(cells.sortedCount(), 6u);
    EXPECT_EQ(p.id[cells.cellStart(home)], 14u);
    cells.setVisitOrder({{0, 3}});
    EXPECT_THROW(cells.sortParticles(p), std::logic_error);
}

namespace {

// A box of 12 planes of 4 x 4 cells, three particles at each x given (a rank's and its ghosts, around
// a rank with planes 0-2), and that rank's home planes (its own and the one before).
struct SlabNeighbourhood {
    Box box;
    Particles p;
    std::vector<std::uint8_t> home = std::vector<std::uint8_t>(12, 0);
    explicit SlabNeighbourhood(std::initializer_list<double> xs) {
        box.lo = Eigen::Vector3d(0, 0, 0);
        box.hi = Eigen::Vector3d(12, 4, 4);
        std::uint64_t id = 0;
        for (const double x : xs)
            for (const double y : {0.5, 2.5, 3.7}) p.add(id++, 0, x, y, std::fmod(x * 7.0 + y, 4.0));
        home[11] = home[0] = home[1] = home[2] = 1;
    }
    // p with one more particle at (x, 1, 1).
    Particles with(double x) const {
        Particles q = p;
        q.add(p.size(), 0, x, 1.0, 1.0);
        return q;
    }
    // p sorted over the whole grid and as the rank sorts it (its home planes, ghostPlanes a side):
    // the same order, and the same cell starts in the planes listed. Returns the rank's cell list.
    CellList expectSameStarts(int ghostPlanes, std::initializer_list<int> planes) const {
        Particles whole = p, windowed = p;
        CellList all, near;
        all.setup(box, 1.0);
        near.setup(box, 1.0);
        near.setHomePlanes(home, ghostPlanes);
        all.sortParticles(whole);
        near.sortParticles(windowed);
        EXPECT_EQ(near.sortedCount(), all.sortedCount());
        EXPECT_EQ(windowed.id, whole.id);
        for (const int ix : planes)
            for (int c = near.cellIndex(ix, 0, 0); c < near.cellIndex(ix, 0, 0) + 16; ++c) {
                EXPECT_EQ(near.cellStart(c), all.cellStart(c)) << "plane " << ix << " cell " << c;
                EXPECT_EQ(near.mobileEnd(c), all.mobileEnd(c));
            }
        return near;
    }
};

}  // namespace

// A rank's sort counts the keys of the planes near its home planes only: the cell starts it keeps
// are those of a sort over the whole grid, on one thread and on three (each thread's share of the
// keys then spans the windows' gap), and a particle outside those planes is refused, not misplaced.
TEST(CellList, WithHomePlanesTheSortKeepsTheStartsOfThePlanesNearThem) {
    // Planes 11, 0, 1, 2 and 3 hold particles (a rank with planes 0-2, its ghosts 11 and 3).
    const SlabNeighbourhood n{11.5, 0.2, 0.7, 1.5, 2.9, 3.1, 11.9};
    for (const int threads : {1, 3}) {
        SCOPED_TRACE(threads);
        omp_set_num_threads(threads);
        // Planes 10-11 and 0-4 (the home planes, one below, two above): every cell start as the whole
        // sort's. The keys of planes 0-4, then those of 10-11: with three threads the last one's
        // share spans the gap between them.
        CellList near = n.expectSameStarts(1, {10, 11, 0, 1, 2, 3, 4});
        // A particle in plane 6, far from the home planes.
        Particles stray = n.with(6.5);
        EXPECT_THROW(near.sortParticles(stray), std::logic_error) << threads;
    }
    omp_set_num_threads(1);
}

// With three ghost planes a side (a rank of a run with chains: parallel/SlabDecomposition::ghostPlanesFor)
// the sort counts the planes of all: around a rank with planes 0-2, the cell starts of planes 9-11
// and 0-6 are the whole sort's, where one ghost plane a side refuses particles in planes 9 and 5.
TEST(CellList, WithThreeGhostPlanesTheSortKeepsTheStartsOfAll) {
    const SlabNeighbourhood n{9.3, 10.2, 11.5, 0.2, 1.5, 2.9, 3.1, 4.6, 5.4, 10.9};
    for (const int threads : {1, 3}) {
        SCOPED_TRACE(threads);
        omp_set_num_threads(threads);
        CellList near = n.expectSameStarts(3, {9, 10, 11, 0, 1, 2, 3, 4, 5, 6});
        Particles stray = n.with(7.5);
        EXPECT_THROW(near.sortParticles(stray), std::logic_error) << threads;
        CellList oneGhostPlane;
        oneGhostPlane.setup(n.box, 1.0);
        oneGhostPlane.setHomePlanes(n.home);
        Particles again = n.p;
        EXPECT_THROW(oneGhostPlane.sortParticles(again), std::logic_error) << threads;
    }
    omp_set_num_threads(1);
}

// The sort is the stable sort by (cell, mobile before frozen) on any number of threads, for particles
// nearly in cell order (a sorted box whose particles then moved up to 0.3 along each axis, some out of
// the box), as every step after the first sorts them: the case where a thread passes over the blocks
// of keys that are not its own (neighbour/SortKeyBlocks.hpp). Large enough for ten blocks a thread.
TEST(CellList, TheSortIsTheStableSortByCellOnAnyNumberOfThreadsWhenNearlySorted) {
    Box box;
    box.lo = Eigen::Vector3d(-3, 0, 0);
    box.hi = Eigen::Vector3d(57, 10, 10);
    Particles start = randomParticles(box, 3.0, 31);
    for (std::size_t k = 0; k < start.size(); ++k) start.species[k] = start.id[k] % 10 == 3 ? 1 : 0;
    const std::vector<std::uint8_t> frozen{0, 1};
    CellList first;
    first.setup(box, 1.0);
    first.sortParticles(start, frozen);
    const PairRandom rng(8);
    for (std::size_t k = 0; k < start.size(); ++k) {
        const auto u = rng.particleUniforms(1, start.id[k], kStreamInitialPosition);
        start.rx[k] += 0.6 * (u[0] - 0.5);
        start.ry[k] += 0.6 * (u[1] - 0.5);
        start.rz[k] += 0.6 * (u[2] - 0.5);
    }
    const int saved = omp_get_max_threads();
    ParticleArray<std::uint64_t> expected;
    for (int threads : {1, 2, 3, 7}) {
        SCOPED_TRACE(std::to_string(threads) + " threads");
        omp_set_num_threads(threads);
        Particles q = start;
        CellList cells;
        cells.setup(box, 1.0);
        cells.sortParticles(q, frozen);
        if (expected.empty()) {  // the reference, from the wrapped positions the sort left
            std::map<std::uint64_t, int> keyOf;
            for (std::size_t k = 0; k < q.size(); ++k)
                keyOf[q.id[k]] = 2 * cells.cellIndex(cells.axisCell(q.rx[k], 0), cells.axisCell(q.ry[k], 1),
                                                     cells.axisCell(q.rz[k], 2)) + frozen[q.species[k]];
            expected = start.id;
            std::stable_sort(expected.begin(), expected.end(),
                             [&](std::uint64_t a, std::uint64_t b) { return keyOf.at(a) < keyOf.at(b); });
            ASSERT_GT(q.size(), 10u * SortKeyBlocks::kBlock * 7);
        }
        EXPECT_EQ(q.id, expected);
        for (int c = 0; c < cells.numCells(); ++c) {
            ASSERT_LE(cells.mobileEnd(c), cells.cellStart(c + 1));
            for (std::uint32_t k = cells.cellStart(c); k < cells.cellStart(c + 1); ++k) {
                ASSERT_EQ(cells.cellIndex(cells.axisCell(q.rx[k], 0), cells.axisCell(q.ry[k], 1), cells.axisCell(q.rz[k], 2)), c);
                ASSERT_EQ(frozen[q.species[k]] != 0, k >= cells.mobileEnd(c)) << "cell " << c;
            }
        }
        EXPECT_EQ(cells.cellStart(cells.numCells()), q.size());
    }
    omp_set_num_threads(saved);
}
