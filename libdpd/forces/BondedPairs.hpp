#pragma once
// How the DPD pair force acts between two bonded particles, `bondedPairs { dpd all; }` in the bonds
// block: all of it (the default, as published), none of it, or `dpd weighted; weight w;` (the
// dissipative term scaled by w and the random one by sqrt(w), so that fluctuation-dissipation still
// holds for the pair; the conservative term is kept).
#include "core/Capabilities.hpp"

#include <string>

namespace dpd {

class Dictionary;

struct BondedPairs {
    enum class Mode { all, none, weighted };
    Mode mode = Mode::all;
    double weight = 1.0;  // weighted: the dissipative factor

    bool keepsAll() const { return mode == Mode::all; }
    // Other than all: the share taken back after the whole pair force reads the velocities.
    Capabilities capabilities() const;
    std::string description() const;
    // From the bonds block (all when it has no bondedPairs); errors name the keyword.
    static BondedPairs read(const Dictionary& bondsBlock);
};

}  // namespace dpd
