#pragma once
// The slip length a channel's tunable-slip walls should give (docs/walls.md 3.5), beside the measured one:
//   b / z_c = 2/alpha - 7/15 - 19 alpha/1800,   alpha = z_c^2 gamma_L rho / eta,   eta = rho nu,
// with rho the fluid's central density and nu its measured kinematic viscosity (the fit's own, or
// slipPredictionNu of system/fitSlipLengthDict).
#include <string>

namespace dpd {

class Dictionary;
struct PlanarWallSettings;

struct TunableSlipPrediction {
    bool any = false;                       // at least one of the two walls has tunable slip
    bool tunable[2] = {false, false};       // lower, upper
    double alpha[2] = {0.0, 0.0};
    double slipLength[2] = {0.0, 0.0};
    double density = 0.0;                   // rho
    double nu = 0.0;                        // kinematic viscosity used
    std::string nuSource;                   // where nu came from
};

// The prediction for the walls that have tunable slip; `any` false (and nothing else set) when neither
// has. Throws std::invalid_argument when a prediction is due but rho or nu is not positive.
TunableSlipPrediction predictTunableSlip(const PlanarWallSettings& lower, const PlanarWallSettings& upper, double density, double nu,
                                         const std::string& nuSource);

// fit.dat entries: slipLengthPredicted (lower upper), slipPredictionAlpha (lower upper) ("none" for a
// wall without tunable slip), slipPredictionNu, slipPredictionNuSource, slipPredictionDensity.
void writeTunableSlipPrediction(Dictionary& d, const TunableSlipPrediction& p);

}  // namespace dpd
