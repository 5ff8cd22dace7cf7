#pragma once
// hydrodynamicWall: where a wall acts and its slip length, from fitSlipLength's Couette and Poiseuille
// fits of the same wall settings (analysis/HydrodynamicWall.hpp, docs/analysis.md 5.3). Each case's
// latest fit.dat is read (the mean of its two walls); the settings pair up in the order given. Printed
// as a dictionary (the format fit.dat uses). With a calibration file named, the settings are a
// tunable-slip wall's frictions and their slip lengths and wall position become a slip calibration.
#include <iosfwd>
#include <string>
#include <vector>

namespace dpd {

struct HydrodynamicWallInput {
    std::vector<std::string> couette;     // cases (or fit.dat files) of the Couette runs, one per setting
    std::vector<std::string> poiseuille;  // the Poiseuille runs of the same settings, in the same order
    // When set, the runs are a tunable-slip wall's friction sweep (cases, not fit.dat files) and the
    // slip calibration they make is written there (walls/SlipCalibration.hpp), whole or not at all.
    std::string calibration;
};

void printHydrodynamicWall(const HydrodynamicWallInput& in, std::ostream& out);

}  // namespace dpd
