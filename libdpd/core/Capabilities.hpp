#pragma once
// What a part of a run (an integrator, a wall, the bonds, a sampler, the run's ranks) declares about
// itself, so that one check pass (case/RunCompatibility.hpp) refuses a combination that cannot run,
// before the first step, at the keyword that asked for it. A part lists the features it brings and
// its refusals: sets of features that, all present in the run, it cannot run beside, and why.
#include <bitset>
#include <initializer_list>
#include <string>
#include <vector>

namespace dpd {

enum class Feature : unsigned {
    severalRanks,            // the run is decomposed over several ranks, a slab of the box each
    velocityForce,           // a force besides the pair force reads the velocities (wall friction, bonded pairs)
    pairForceTakenBack,      // part of the whole DPD pair force is taken back after the pair loop (bondedPairs)
    movesAlongXAfterSort,    // particles move after the step's sort, along x (bounceForward, normal with an x part)
    count
};

class Features {
public:
    Features() = default;
    Features(std::initializer_list<Feature> fs) {
        for (Feature f : fs) add(f);
    }
    void add(Feature f) { bits_.set(static_cast<unsigned>(f)); }
    bool has(Feature f) const { return bits_.test(static_cast<unsigned>(f)); }
    bool any() const { return bits_.any(); }
    bool containsAll(const Features& other) const { return (bits_ & other.bits_) == other.bits_; }
    bool sharesAny(const Features& other) const { return (bits_ & other.bits_).any(); }
    Features& operator|=(const Features& other) {
        bits_ |= other.bits_;
        return *this;
    }

private:
    std::bitset<static_cast<unsigned>(Feature::count)> bits_;
};

// A part cannot run where all of `together` are present: `why` completes "<part> <why>". The
// keyword, when given, is the part's own keyword that asks for what cannot run (else its type).
struct Refusal {
    Features together;
    std::string why;
    std::string keyword;
};

struct Capabilities {
    Features features;
    std::vector<Refusal> refusals;
};

}  // namespace dpd
