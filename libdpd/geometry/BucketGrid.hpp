#pragma once
// A periodic bucket grid over a geometry's coordinates: items (mesh elements, surface facets) are
// filed under every bucket their bounding box touches, so "which items are near this point" costs
// O(1) buckets. Used for point location in a gmsh mesh and for nearest-facet searches.
#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace dpd {

class BucketGrid {
public:
    BucketGrid() = default;
    // Buckets of about bucketSize (larger if there would be more than about 4 million) over
    // [lo, lo + period) along the first `dimension` axes.
    BucketGrid(int dimension, const Eigen::Vector3d& lo, const Eigen::Vector3d& period, double bucketSize);

    // Collect with add(), then call build() once before any query.
    void add(std::uint32_t item, const Eigen::Vector3d& bboxLo, const Eigen::Vector3d& bboxHi);
    void build();

    // Calls f(item) for every item filed in a bucket within `radius` of p (an item may come more than
    // once when it spans several of them).
    template <class F>
    void forEachNear(const Eigen::Vector3d& p, double radius, F&& f) const {
        int from[3] = {0, 0, 0}, count[3] = {1, 1, 1};
        for (int a = 0; a < dimension_; ++a) {
            const int first = bucketCoordinate(p[a] - radius, a), last = bucketCoordinate(p[a] + radius, a);
            from[a] = first;
            count[a] = std::min(last - first + 1, n_[a]);
        }
        for (int k = 0; k < count[2]; ++k)
            for (int j = 0; j < count[1]; ++j)
                for (int i = 0; i < count[0]; ++i) {
                    const std::size_t b = bucket(from[0] + i, from[1] + j, from[2] + k);
                    for (std::uint32_t s = start_[b]; s < start_[b + 1]; ++s) f(items_[s]);
                }
    }

private:
    int bucketCoordinate(double x, int axis) const;  // unwrapped
    std::size_t bucket(int i, int j, int k) const;   // wraps
    int dimension_ = 3;
    Eigen::Vector3d lo_{0, 0, 0}, size_{1, 1, 1};
    int n_[3] = {1, 1, 1};
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pending_;  // (bucket, item)
    std::vector<std::uint32_t> start_, items_;
};

}  // namespace dpd
