#pragma once
// A slip calibration of known form for the tests of walls/SlipCalibration and of walls that ask for
// a slip length: the standard fluid at dt 0.01, the wall model with the fluid behind, and
// b = 3 / gamma_L - 0.4 exactly (the form of the small-alpha prediction) at four frictions.
#include "walls/SlipCalibration.hpp"

#include <vector>

namespace dpd::test {

inline SlipCalibrationKey standardFluidSlipKey() {
    SlipCalibrationKey k;
    k.density = 3;
    k.a = 25;
    k.gamma = 4.5;
    k.kT = 1;
    k.dt = 0.01;
    k.integrator = "GrootWarren lambda 0.65";
    TunableSlipParameters wall;  // z_c 1, epsilon 1, sigma 0.5
    wall.behindA = 25;
    wall.behindDensity = 3;
    k.setWallModel(wall);
    return k;
}

// b from 11.6 (gamma_L 0.25) down to -0.025 (gamma_L 8); the wall acts 0.3 +- 0.02 in front of its plane.
inline SlipCalibration exactSlipCalibration(SlipCalibrationKey key = standardFluidSlipKey()) {
    std::vector<SlipCalibrationPoint> points;
    for (double g : {8.0, 0.5, 2.0, 0.25}) points.push_back({g, 3.0 / g - 0.4, 0.01 * g});
    return SlipCalibration(key, points, 0.3, 0.02, "test");
}

}  // namespace dpd::test
