#pragma once
// hydrodynamicWall: where a wall acts and its slip length, from fitSlipLength's Couette and Poiseuille
// fits of the same wall settings (analysis/HydrodynamicWall.hpp, docs/analysis.md 5.3). Each case's
// latest fit.dat is read (the mean of its two walls); the settings pair up in the order given. Printed
// as a dictionary (the format fit.dat uses).
#include <iosfwd>
#include <string>
#include <vector>

namespace dpd {

struct HydrodynamicWallInput {
    std::vector<std::string> couette;     // cases (or fit.dat files) of the Couette runs, one per setting
    std::vector<std::string> poiseuille;  // the Poiseuille runs of the same settings, in the same order
};

void printHydrodynamicWall(const HydrodynamicWallInput& in, std::ostream& out);

}  // namespace dpd
