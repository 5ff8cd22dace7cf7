#pragma once
// The scenes dpdBenchmark times: the standard DPD fluid in a periodic box, the same with chains, and a channel between
// frozen fcc walls with bounce-back (the FCC walls of tutorials/channel/poiseuille/fcc, bounce-back in place of their bounce layer, scaled to the
// particle count), sampled every step by a binned profile as a run would be.
#include "system/System.hpp"
#include "sampling/FunctionObjects.hpp"

#include <string>

namespace dpd {

struct BenchmarkScene {
    std::string name;
    System system;               // initialised, sorted, forces computed
    FunctionObjects sampling;    // empty for the bare fluid
    int flowAxis = -1;           // for the temperature about the local flow (monitor)
};

// The standard fluid: rho 3, a (25 by default; 0 drops the conservative term), gamma 4.5, kT 1,
// dt 0.04, about `particles` particles. On several ranks (mpirun) `particles` per rank, in a box as
// many cubes long along x as there are ranks, decomposed in slabs: a weak-scaling measurement.
BenchmarkScene makeFluidScene(std::size_t particles, double a, int dimension, const Communicator& ranks);

// The standard fluid with 10 % of its particles in chains of 30 beads (FENE, H 6, r_max 3): what
// bonds cost. On several ranks as the fluid (weak scaling), with three ghost planes a side (r_max).
BenchmarkScene makeChainsScene(std::size_t particles, double a, const Communicator& ranks);

// The channel: walls at z = -10 and 10 with one cutoff of frozen fcc lattice behind each, rho 4,
// a 18.75, gamma 4.5, body force 0.02 along x, bounce-back, dt 0.04, a square cross-section sized
// for about `particles` particles (walls included), a 44-bin profile across z sampled every step.
BenchmarkScene makeChannelScene(std::size_t particles);

// Flow through grains: a cube holding about `particles` fluid particles (the fluid scene's: rho 3,
// a 25, gamma 4.5) in its pores, half of it solid (discs of a square lattice about 8 cutoffs apart,
// an image mask extruded along y, distance field of cells 1/8 cutoff), frozen particles at the
// same density one cutoff deep in the grains, a bounce layer 0.1 thick, body force 0.01 along x, an
// x-z grid of bins sampled every fifth step. Its rate counts the fluid particles, as a run's log does.
BenchmarkScene makeGeometryScene(std::size_t particles);

}  // namespace dpd
