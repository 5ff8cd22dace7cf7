#include "geometry/BucketGrid.hpp"

#include <algorithm>
#include <cmath>

namespace dpd {

BucketGrid::BucketGrid(int dimension, const Eigen::Vector3d& lo, const Eigen::Vector3d& period, double bucketSize)
    : dimension_(dimension), lo_(lo) {
    const int maxPerAxis = dimension == 3 ? 160 : 2048;
    for (int a = 0; a < dimension; ++a) {
        n_[a] = std::clamp(static_cast<int>(period[a] / bucketSize), 1, maxPerAxis);
        size_[a] = period[a] / n_[a];
    }
}

int BucketGrid::bucketCoordinate(double x, int axis) const {
    return static_cast<int>(std::floor((x - lo_[axis]) / size_[axis]));
}

std::size_t BucketGrid::bucket(int i, int j, int k) const {
    const auto wrap = [](int c, int n) { return ((c % n) + n) % n; };
    return (static_cast<std::size_t>(wrap(k, n_[2])) * n_[1] + wrap(j, n_[1])) * n_[0] + wrap(i, n_[0]);
}

void BucketGrid::add(std::uint32_t item, const Eigen::Vector3d& bboxLo, const Eigen::Vector3d& bboxHi) {
    int from[3] = {0, 0, 0}, count[3] = {1, 1, 1};
    for (int a = 0; a < dimension_; ++a) {
        from[a] = bucketCoordinate(bboxLo[a], a);
        count[a] = std::min(bucketCoordinate(bboxHi[a], a) - from[a] + 1, n_[a]);
    }
    for (int k = 0; k < count[2]; ++k)
        for (int j = 0; j < count[1]; ++j)
            for (int i = 0; i < count[0]; ++i)
                pending_.emplace_back(static_cast<std::uint32_t>(bucket(from[0] + i, from[1] + j, from[2] + k)), item);
}

void BucketGrid::build() {
    // Counting sort by bucket into one flat array (compressed rows).
    const std::size_t nBuckets = static_cast<std::size_t>(n_[0]) * n_[1] * n_[2];
    start_.assign(nBuckets + 1, 0);
    for (const auto& [b, item] : pending_) ++start_[b + 1];
    for (std::size_t b = 0; b < nBuckets; ++b) start_[b + 1] += start_[b];
    items_.resize(pending_.size());
    std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
    for (const auto& [b, item] : pending_) items_[fill[b]++] = item;
    pending_.clear();
    pending_.shrink_to_fit();
}

}  // namespace dpd
