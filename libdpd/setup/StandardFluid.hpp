#pragma once
// A periodic box of one DPD fluid: the standard scene for benchmarks and physics tests.
#include "system/System.hpp"

namespace dpd {

struct StandardFluidSettings {
    std::size_t particles = 3000;
    double density = 3.0;
    double a = 25.0;
    double gamma = 4.5;
    double kT = 1.0;
    double dt = 0.04;
    double cutoff = 1.0;
    int dimension = 3;
    std::uint64_t seed = 1;
    // Relative edge lengths x y z (y unused in 2-D); the volume stays particles / density.
    Eigen::Vector3d aspect{1.0, 1.0, 1.0};
    // Several ranks: the box is cut in slabs and this process keeps its own (System::ranks).
    const Communicator* ranks = nullptr;
};

// A box (cubic, square in 2-D, unless `aspect` says otherwise) holding about `particles` at the density, random positions, Maxwellian
// velocities with zero total momentum, initialised with forces computed.
System makeStandardFluid(const StandardFluidSettings& s);

}  // namespace dpd
