#pragma once
// What a slip calibration is keyed by (walls/SlipCalibration.hpp), read from one of its runs' cases: a
// channel between planar tunable-slip walls of one model and one friction. The fluid comes from
// constant/dpdProperties (the self pair of its one mobile species, kT, cutoff, dimension, the
// integrator with its coefficients) and system/blockFrozenWallDict (fluid/density), the step from
// system/controlDict (deltaT), the wall model and gamma_L from the walls.
#include "walls/SlipCalibration.hpp"

#include <string>

namespace dpd {

struct CalibrationCase {
    SlipCalibrationKey key;
    double gammaL = 0.0;  // the friction its walls share
};

// InputError at the entry for a case that is not such a channel: not exactly one mobile species, a
// wall that is not a planar tunable-slip wall, walls of different models or frictions, stripes.
CalibrationCase readCalibrationCase(const std::string& caseDir);

}  // namespace dpd
