#pragma once
// Test scenes with polymer chains: setup/ChainedFluid (the standard fluid with chains, FENE H 6,
// rMax 3, every pair with the fluid's coefficients).
#include "forces/FeneBond.hpp"
#include "setup/ChainedFluid.hpp"

namespace dpd::test {

using ChainScene = ChainedFluidSettings;
inline System makeChainedFluid(const ChainScene& scene) { return dpd::makeChainedFluid(scene); }

}  // namespace dpd::test
