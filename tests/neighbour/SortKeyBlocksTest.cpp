// SortKeyBlocks: a pass over a range of keys visits exactly the indices a plain scan visits, in the
// same order, and skips the blocks that hold none of them.
#include "neighbour/SortKeyBlocks.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

namespace dpd {
namespace {

// Keys nearly in order (a sorted run whose particles moved: a tenth of them jump up to 40 keys, one in
// a thousand anywhere), as a cell list's keys look one sort after the last.
std::vector<std::uint32_t> nearlySortedKeys(std::uint32_t n, std::uint32_t nKeys, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<std::uint32_t> key(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        auto k = static_cast<std::int64_t>(std::uint64_t(i) * nKeys / n);
        const double r = u(rng);
        if (r < 0.001) k = static_cast<std::int64_t>(u(rng) * nKeys);
        else if (r < 0.1) k += static_cast<std::int64_t>((u(rng) - 0.5) * 80.0);
        key[i] = static_cast<std::uint32_t>(std::clamp<std::int64_t>(k, 0, nKeys - 1));
    }
    return key;
}

SortKeyBlocks blocksOf(const std::vector<std::uint32_t>& key) {
    SortKeyBlocks blocks;
    const auto n = static_cast<std::uint32_t>(key.size());
    blocks.resize(n);
    for (std::uint32_t s = 0; s < n; s += SortKeyBlocks::kBlock)
        blocks.record(s, key.data() + s, std::min(SortKeyBlocks::kBlock, n - s));
    return blocks;
}

std::vector<std::uint32_t> plainScan(const std::vector<std::uint32_t>& key, std::uint32_t first, std::uint32_t end,
                                     std::uint32_t kBegin, std::uint32_t width) {
    std::vector<std::uint32_t> found;
    for (std::uint32_t i = first; i < end; ++i)
        if (key[i] - kBegin < width) found.push_back(i);
    return found;
}

}  // namespace

TEST(SortKeyBlocks, VisitsWhatAPlainScanVisitsInItsOrder) {
    const std::uint32_t n = 10'000 + 37, nKeys = 3'000;  // a last block part full
    std::vector<std::uint32_t> key = nearlySortedKeys(n, nKeys, 5);
    SortKeyBlocks blocks = blocksOf(key);
    // A key changed after recording (a discarded particle's, the greatest) is found through widen.
    key[4'321] = nKeys;
    blocks.widen(4'321, nKeys);
    // Ranges of keys as threads split them (1 to 16 threads), the discarded key's own, and ranges of
    // indices that start and end inside blocks (a decomposed run's visit order).
    const std::vector<std::pair<std::uint32_t, std::uint32_t>> indexRanges{{0, n}, {100, 9'000}, {300, 301}, {4'000, 4'600}};
    std::size_t visited = 0, scanned = 0;
    for (const auto& [first, end] : indexRanges)
        for (std::uint32_t threads : {1u, 2u, 3u, 16u})
            for (std::uint32_t t = 0; t <= threads; ++t) {
                const std::uint32_t kBegin = t == threads ? nKeys : (nKeys + 1) * t / threads;
                const std::uint32_t kEnd = t == threads ? nKeys + 1 : (nKeys + 1) * (t + 1) / threads;
                std::vector<std::uint32_t> found;
                blocks.forEachKeyIn(key.data(), first, end, kBegin, kEnd - kBegin, [&](std::uint32_t i) {
                    found.push_back(i);
                    ++visited;
                });
                ASSERT_EQ(found, plainScan(key, first, end, kBegin, kEnd - kBegin))
                    << "indices " << first << "-" << end << ", keys " << kBegin << "-" << kEnd;
                scanned += end - first;
            }
    EXPECT_GT(visited, 0u);
    EXPECT_GT(scanned, visited);
}

TEST(SortKeyBlocks, PassesOverTheBlocksWhoseBoundsMissTheRange) {
    // Keys written after the bounds were recorded, without widen, are read only in blocks whose
    // recorded bounds meet the range: in a block recorded as all 10, keys 15 are not seen from 15 .. 15,
    // and are seen from a range that also holds 10.
    const std::uint32_t n = 4 * SortKeyBlocks::kBlock;
    std::vector<std::uint32_t> key(n, 10);
    const SortKeyBlocks blocks = blocksOf(key);
    std::fill(key.begin() + SortKeyBlocks::kBlock, key.end(), 15u);
    const auto count = [&](std::uint32_t kBegin, std::uint32_t width) {
        std::size_t c = 0;
        blocks.forEachKeyIn(key.data(), 0, n, kBegin, width, [&](std::uint32_t) { ++c; });
        return c;
    };
    EXPECT_EQ(count(15, 1), 0u);
    EXPECT_EQ(count(10, 6), n);
}

TEST(SortKeyBlocks, ABlockIsSkippedOnlyWhenItHoldsNoKeyOfTheRange) {
    // One block with keys 10 and 20 only: ranges between them, touching either end, and around both.
    std::vector<std::uint32_t> key(SortKeyBlocks::kBlock, 10);
    key[17] = 20;
    const SortKeyBlocks blocks = blocksOf(key);
    const auto count = [&](std::uint32_t kBegin, std::uint32_t width) {
        std::size_t c = 0;
        blocks.forEachKeyIn(key.data(), 0, SortKeyBlocks::kBlock, kBegin, width, [&](std::uint32_t) { ++c; });
        return c;
    };
    EXPECT_EQ(count(11, 9), 0u);                            // 11..19: inside the bounds, no key
    EXPECT_EQ(count(20, 1), 1u);                            // the greatest alone
    EXPECT_EQ(count(0, 11), SortKeyBlocks::kBlock - 1);     // 0..10: the least
    EXPECT_EQ(count(5, 100), SortKeyBlocks::kBlock);        // both
    EXPECT_EQ(count(21, 1'000), 0u);                        // above
    EXPECT_EQ(count(0, 10), 0u);                            // below
}

TEST(SortKeyBlocks, CoveringEveryKeyVisitsWhatAPlainScanVisits) {
    // The one-thread sort records no bounds: every block is read, stale bounds or none.
    const std::uint32_t n = 3 * SortKeyBlocks::kBlock + 5, nKeys = 400;
    std::vector<std::uint32_t> key = nearlySortedKeys(n, nKeys, 7);
    SortKeyBlocks blocks = blocksOf(std::vector<std::uint32_t>(n, 0));  // bounds of other keys
    blocks.coverEveryKey();
    for (const auto& [kBegin, width] : std::vector<std::pair<std::uint32_t, std::uint32_t>>{{0, nKeys}, {399, 1}, {150, 20}}) {
        std::vector<std::uint32_t> found;
        blocks.forEachKeyIn(key.data(), 0, n, kBegin, width, [&](std::uint32_t i) { found.push_back(i); });
        EXPECT_EQ(found, plainScan(key, 0, n, kBegin, width)) << "keys " << kBegin << " + " << width;
        EXPECT_FALSE(found.empty());
    }
}

}  // namespace dpd
