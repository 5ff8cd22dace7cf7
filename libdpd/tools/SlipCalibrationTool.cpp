#include "tools/SlipCalibrationTool.hpp"

#include "io/Dictionary.hpp"
#include "walls/SlipCalibration.hpp"

#include <iomanip>
#include <ostream>
#include <sstream>
#include <stdexcept>

namespace dpd {

namespace {

void printList(std::ostream& out, const char* name, const std::vector<CalibratedFriction>& walls,
               double CalibratedFriction::*member) {
    out << std::setw(16) << std::left << name << "(";
    for (std::size_t k = 0; k < walls.size(); ++k) out << (k ? " " : "") << walls[k].*member;
    out << ");\n";
}

}  // namespace

void printSlipCalibration(const SlipCalibrationQuery& q, std::ostream& out) {
    const SlipCalibration calibration = SlipCalibration::read(Dictionary::readFile(q.file));
    std::vector<CalibratedFriction> walls;
    std::vector<double> leftSlips;
    for (double b : q.slipLengths) {
        try {
            walls.push_back(calibration.wallFor(b));
        } catch (const std::out_of_range& e) {
            throw std::invalid_argument("-slipLength: " + std::string(e.what()));
        }
        // What the plane moved out by leaves on top of b (below the range, the stiffest friction's slip).
        leftSlips.push_back(b + (calibration.wallOffset() - walls.back().planeOffset));
    }
    out << std::setprecision(10) << std::left;
    out << std::setw(16) << "calibration" << '"' << q.file << "\";\n"
        << std::setw(16) << "wallOffset" << calibration.wallOffset() << ";\n"
        << std::setw(16) << "wallOffsetError" << calibration.wallOffsetError() << ";\n"
        << std::setw(16) << "smallestSlip" << calibration.smallestSlip() << ";\n"
        << std::setw(16) << "largestSlip" << calibration.largestSlip() << ";\n";
    if (walls.empty()) return;
    out << std::setw(16) << "slipLength" << "(";
    for (std::size_t k = 0; k < q.slipLengths.size(); ++k) out << (k ? " " : "") << q.slipLengths[k];
    out << ");\n";
    printList(out, "gammaL", walls, &CalibratedFriction::gammaL);
    printList(out, "slipLengthError", walls, &CalibratedFriction::slipLengthError);
    printList(out, "planeOffset", walls, &CalibratedFriction::planeOffset);
    out << std::setw(16) << "slipLeft" << "(";
    for (std::size_t k = 0; k < leftSlips.size(); ++k) out << (k ? " " : "") << leftSlips[k];
    out << ");\n";
}

}  // namespace dpd
