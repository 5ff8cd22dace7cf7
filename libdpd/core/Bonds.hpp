#pragma once
// Bonds between particles (the springs of polymer chains, docs/methods.md section 4): which particles
// are joined, by permanent id (ids survive sorting, restarts and wrapping), the chain each bond belongs
// to, and the bond's vector r_second - r_first as the pair sees it. The vector is kept and followed
// from step to step rather than taken as the minimum image: in a box thinner than two bond lengths (the
// published channel is 3 thick and r_max = 3) the minimum image can pick the wrong copy of a bead.
#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace dpd {

struct Bonds {
    std::vector<std::uint64_t> first, second;  // particle ids
    std::vector<std::int64_t> chain;           // chains are numbered 0, 1, ...; a bead lies in one chain
    std::vector<double> bx, by, bz;            // r_second - r_first, not wrapped

    std::size_t size() const { return first.size(); }
    bool empty() const { return first.empty(); }
    void add(std::uint64_t a, std::uint64_t b, std::int64_t chainIndex, const Eigen::Vector3d& vector) {
        first.push_back(a);
        second.push_back(b);
        chain.push_back(chainIndex);
        bx.push_back(vector.x());
        by.push_back(vector.y());
        bz.push_back(vector.z());
    }
    Eigen::Vector3d vector(std::size_t k) const { return {bx[k], by[k], bz[k]}; }
};

}  // namespace dpd
