#include "setup/ChainBuilder.hpp"

#include "geometry/BucketGrid.hpp"
#include "io/Dictionary.hpp"
#include "random/PairRandom.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace dpd {

namespace {

// The builder's own stream of uniforms for one chain (counter-based: the same seed, the same chains).
class ChainRandom {
public:
    ChainRandom(std::uint64_t seed, std::uint64_t chain) : random_(seed), chain_(chain) {}
    double uniform() {
        if (next_ == 4) {
            values_ = random_.particleUniforms(draw_++, chain_, kStreamChainBuilder);
            next_ = 0;
        }
        return values_[next_++];
    }

private:
    PairRandom random_;
    std::uint64_t chain_;
    std::uint64_t draw_ = 0;
    std::array<double, 4> values_{};
    int next_ = 4;
};

// Bond lengths from p(r) ~ r^(d-1) exp(-U(r)/kT) on (0, rMax), by rejection under its maximum.
class BondLengthSampler {
public:
    BondLengthSampler(const BondPotential& bond, double kT, int dimension)
        : bond_(bond), kT_(kT), dimension_(dimension), rMax_(std::min(bond.maxLength(), 10.0)) {
        for (int k = 1; k < 4000; ++k) peak_ = std::max(peak_, density(rMax_ * k / 4000.0));
        peak_ *= 1.01;  // the grid may miss the true maximum by a little
    }
    double draw(ChainRandom& random) const {
        for (;;) {
            const double r = rMax_ * random.uniform();
            if (random.uniform() * peak_ < density(r)) return r;
        }
    }

private:
    double density(double r) const { return std::pow(r, dimension_ - 1) * std::exp(-bond_.energy(r) / kT_); }
    const BondPotential& bond_;
    double kT_;
    int dimension_;
    double rMax_;
    double peak_ = 0.0;
};

Eigen::Vector3d randomDirection(ChainRandom& random, int dimension) {
    const double phi = 2.0 * M_PI * random.uniform();
    if (dimension == 2) return {std::cos(phi), 0.0, std::sin(phi)};
    const double cosTheta = 2.0 * random.uniform() - 1.0;
    const double sinTheta = std::sqrt(1.0 - cosTheta * cosTheta);
    return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

Eigen::Vector3d wrapped(const Box& box, Eigen::Vector3d r) {
    box.wrapPoint(r.x(), r.y(), r.z());
    return r;
}

double minimumImageDistance(const Box& box, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    Eigen::Vector3d d = a - b;
    for (int axis = 0; axis < 3; ++axis)
        if (box.isActiveAxis(axis)) d[axis] -= box.length()[axis] * std::nearbyint(d[axis] / box.length()[axis]);
    return d.norm();
}

// The fluid particles still free to become beads, and the nearest of them to a point.
class FluidPool {
public:
    FluidPool(const Snapshot& s, int fluidSpecies) : box_(s.box), p_(s.particles), used_(s.particles.size(), true) {
        grid_ = BucketGrid(3, box_.lo, box_.length(), 1.0);
        for (std::size_t i = 0; i < p_.size(); ++i) {
            if (p_.species[i] != fluidSpecies) continue;
            const Eigen::Vector3d r = position(i);
            grid_.add(static_cast<std::uint32_t>(i), r, r);
            used_[i] = false;
            ++free_;
        }
        grid_.build();
    }
    long free() const { return free_; }
    Eigen::Vector3d position(std::size_t i) const { return wrapped(box_, {p_.rx[i], p_.ry[i], p_.rz[i]}); }
    bool isFree(std::size_t i) const { return !used_[i]; }
    // The nearest free particle and its distance; throws when none is left.
    std::pair<std::size_t, double> nearest(const Eigen::Vector3d& r) const {
        const double farthest = box_.length().maxCoeff();
        for (double radius = 1.0;; radius *= 2.0) {
            std::size_t best = p_.size();
            double bestDistance = std::numeric_limits<double>::infinity();
            grid_.forEachNear(r, radius, [&](std::uint32_t i) {
                if (used_[i]) return;
                const double d = minimumImageDistance(box_, r, position(i));
                if (d < bestDistance || (d == bestDistance && i < best)) { best = i; bestDistance = d; }
            });
            if (best < p_.size() && (bestDistance <= radius || radius > farthest)) return {best, bestDistance};
            if (radius > farthest) throw std::invalid_argument("insertChains: no fluid particle left to become a bead");
        }
    }
    void take(std::size_t i) { used_[i] = true; --free_; }

private:
    const Box& box_;
    const Particles& p_;
    std::vector<bool> used_;
    BucketGrid grid_;
    long free_ = 0;
};

int speciesIndex(const Snapshot& s, const std::string& name) {
    for (std::size_t k = 0; k < s.speciesNames.size(); ++k)
        if (s.speciesNames[k] == name) return static_cast<int>(k);
    return -1;
}

// One walk of `length` beads (unwrapped positions), every bead at least `clear` from a solid; empty
// when it ran into a dead end.
std::vector<Eigen::Vector3d> walk(const Eigen::Vector3d& start, long length, const BondLengthSampler& lengths,
                                  ChainRandom& random, const Box& box, const ClearanceFunction& clearance, double clear) {
    std::vector<Eigen::Vector3d> beads{start};
    while (static_cast<long>(beads.size()) < length) {
        bool placed = false;
        for (int attempt = 0; attempt < 100 && !placed; ++attempt) {
            const Eigen::Vector3d next = beads.back() + lengths.draw(random) * randomDirection(random, box.dimension);
            if (clearance(wrapped(box, next)) < clear) continue;
            beads.push_back(next);
            placed = true;
        }
        if (!placed) return {};
    }
    return beads;
}

}  // namespace

ChainSettings ChainSettings::read(const Dictionary& d, double kT) {
    d.checkKeys({"chains", "length", "species", "replace", "clearance", "seed"});
    ChainSettings s;
    s.chains = d.get<long>("chains");
    if (s.chains < 0) d.fail("chains", "must not be negative");
    s.length = d.get<long>("length");
    if (s.length < 2 && s.chains > 0) d.fail("length", "must be at least 2 (beads per chain)");
    s.beadSpecies = d.get<std::string>("species");
    s.fluidSpecies = d.getOrDefault<std::string>("replace", "fluid");
    s.clearance = d.getOrDefault<double>("clearance", 0.5);
    if (!(s.clearance >= 0.0)) d.fail("clearance", "must not be negative");
    const long seed = d.getOrDefault<long>("seed", 1);
    if (seed < 0) d.fail("seed", "must not be negative");
    s.seed = static_cast<std::uint64_t>(seed);
    s.kT = kT;
    return s;
}

ChainReport insertChains(Snapshot& s, const ChainSettings& settings, const BondPotential& bond,
                         const ClearanceFunction& clearance) {
    if (!s.bonds.empty()) throw std::invalid_argument("insertChains: the snapshot already holds chains (build the case again)");
    const int beadSpecies = speciesIndex(s, settings.beadSpecies), fluidSpecies = speciesIndex(s, settings.fluidSpecies);
    if (beadSpecies < 0) {
        s.speciesNames.push_back(settings.beadSpecies);
        s.speciesFrozen.resize(s.speciesNames.size() - 1, false);
        s.speciesFrozen.push_back(false);
    }
    if (fluidSpecies < 0) throw std::invalid_argument("insertChains: the snapshot has no species '" + settings.fluidSpecies + "'");
    const auto bead = static_cast<std::uint8_t>(beadSpecies >= 0 ? beadSpecies : static_cast<int>(s.speciesNames.size()) - 1);
    FluidPool pool(s, fluidSpecies);
    if (pool.free() < settings.chains * settings.length)
        throw std::invalid_argument("insertChains: " + std::to_string(settings.chains * settings.length) + " beads but only " +
                                    std::to_string(pool.free()) + " particles of species '" + settings.fluidSpecies + "'");
    const BondLengthSampler lengths(bond, settings.kT, s.box.dimension);
    ChainReport report;
    double bondLengthSum = 0.0;
    Particles& p = s.particles;
    for (long c = 0; c < settings.chains; ++c) {
        ChainRandom random(settings.seed, static_cast<std::uint64_t>(c));
        std::vector<Eigen::Vector3d> beads;
        while (beads.empty()) {
            if (report.restarts > 1000 * (settings.chains + 1))
                throw std::invalid_argument("insertChains: no room for chain " + std::to_string(c) + " clear of the solids by " +
                                            std::to_string(settings.clearance));
            const std::size_t first = static_cast<std::size_t>(random.uniform() * p.size()) % p.size();
            const Eigen::Vector3d start = pool.position(first);  // a free fluid particle's place
            if (pool.isFree(first) && clearance(start) >= settings.clearance)
                beads = walk(start, settings.length, lengths, random, s.box, clearance, settings.clearance);
            if (beads.empty()) ++report.restarts;
        }
        std::uint64_t previous = 0;
        for (std::size_t b = 0; b < beads.size(); ++b) {
            const Eigen::Vector3d r = wrapped(s.box, beads[b]);
            const auto [i, moved] = pool.nearest(r);
            pool.take(i);
            report.largestMove = std::max(report.largestMove, moved);
            p.rx[i] = r.x(); p.ry[i] = r.y(); p.rz[i] = r.z();
            p.species[i] = bead;
            if (b > 0) {
                s.bonds.add(previous, p.id[i], c, beads[b] - beads[b - 1]);
                bondLengthSum += (beads[b] - beads[b - 1]).norm();
            }
            previous = p.id[i];
        }
        report.beads += static_cast<long>(beads.size());
    }
    // The moved particles' stored forces belong to their old places: the run computes all anew.
    for (std::size_t i = 0; i < p.size(); ++i) p.fx[i] = p.fy[i] = p.fz[i] = 0.0;
    report.meanBondLength = s.bonds.empty() ? 0.0 : bondLengthSum / static_cast<double>(s.bonds.size());
    return report;
}

}  // namespace dpd
