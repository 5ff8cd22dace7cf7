#include "tools/SlipCalibrationTool.hpp"

#include "io/Dictionary.hpp"
#include "walls/SlipCalibration.hpp"

#include <iomanip>
#include <ostream>
#include <sstream>
#include <stdexcept>

namespace dpd {

namespace {

void printList(std::ostream& out, const char* name, const std::vector<double>& values) {
    out << std::setw(16) << std::left << name << "(";
    for (std::size_t k = 0; k < values.size(); ++k) out << (k ? " " : "") << values[k];
    out << ");\n";
}

}  // namespace

void printSlipCalibration(const SlipCalibrationQuery& q, std::ostream& out) {
    const SlipCalibration calibration = SlipCalibration::read(Dictionary::readFile(q.file));
    std::vector<double> gammas, errors, planes, left;
    for (double b : q.slipLengths) {
        CalibratedFriction wall;
        try {
            wall = calibration.wallFor(b);
        } catch (const std::out_of_range& e) {
            throw std::invalid_argument("-slipLength: " + std::string(e.what()));
        }
        gammas.push_back(wall.gammaL);
        errors.push_back(wall.slipLengthError);
        planes.push_back(wall.planeOffset);
        // What the plane moved out by leaves on top of b (below the range, the stiffest friction's slip).
        left.push_back(b + (calibration.wallOffset() - wall.planeOffset));
    }
    out << std::setprecision(10) << std::left;
    out << std::setw(16) << "calibration" << '"' << q.file << "\";\n"
        << std::setw(16) << "wallOffset" << calibration.wallOffset() << ";\n"
        << std::setw(16) << "wallOffsetError" << calibration.wallOffsetError() << ";\n"
        << std::setw(16) << "smallestSlip" << calibration.smallestSlip() << ";\n"
        << std::setw(16) << "largestSlip" << calibration.largestSlip() << ";\n";
    if (q.slipLengths.empty()) return;
    printList(out, "slipLength", q.slipLengths);
    printList(out, "gammaL", gammas);
    printList(out, "slipLengthError", errors);
    printList(out, "planeOffset", planes);
    printList(out, "slipLeft", left);
}

}  // namespace dpd
