#pragma once
// slipCalibration: what a slip calibration (walls/SlipCalibration.hpp, docs/walls.md 3.7) holds and the
// wall it gives each asked slip length, as dpdFoamLike's walls that ask `slipLength b;` take it (3.8):
// the friction gamma_L, the calibration's error of b there, how far behind where the wall is put its
// plane goes, and the slip the friction leaves from where the wall acts (b itself within the
// calibrated range; below it, the stiffest friction's). Printed as a dictionary (fit.dat's format), so
// that scripts pick frictions as the engine does instead of interpolating again.
#include <iosfwd>
#include <string>
#include <vector>

namespace dpd {

struct SlipCalibrationQuery {
    std::string file;                 // the calibration
    std::vector<double> slipLengths;  // asked b, each within 0 .. the largest calibrated
};

// InputError naming the file and entry for a bad calibration; std::invalid_argument naming -slipLength
// and the calibrated range for a b outside 0 .. the largest calibrated slip length.
void printSlipCalibration(const SlipCalibrationQuery& q, std::ostream& out);

}  // namespace dpd
