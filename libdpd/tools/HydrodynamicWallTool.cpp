#include "tools/HydrodynamicWallTool.hpp"

#include "analysis/HydrodynamicWall.hpp"
#include "core/Error.hpp"
#include "foam/FoamCaseSpec.hpp"
#include "io/Dictionary.hpp"
#include "tools/SlipCalibrationCase.hpp"

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <ostream>
#include <stdexcept>

namespace dpd {

namespace {

struct WallsMean {
    double slip = 0.0, slipErr = 0.0;
    double width = 0.0;
    std::string file;
};

// The mean slip length of the two walls of one fit.dat, and the channel's geometric width.
WallsMean readFit(const std::string& fileOrCase, const std::string& mode) {
    WallsMean m;
    m.file = findFitFile(fileOrCase);
    const Dictionary fit = Dictionary::readFile(m.file);
    if (fit.get<std::string>("mode") != mode)
        fit.fail("mode", "is " + fit.get<std::string>("mode") + ": give the " + mode + " runs after -" + mode);
    const auto two = [&](const char* key) {
        const std::vector<double> v = fit.get<std::vector<double>>(key);
        if (v.size() != 2) fit.fail(key, "expected two values, one per wall");
        return v;
    };
    const std::vector<double> walls = two("wallPosition"), slip = two("slipLength"), err = two("slipLengthError");
    m.width = walls[1] - walls[0];
    m.slip = 0.5 * (slip[0] + slip[1]);
    m.slipErr = 0.5 * std::hypot(err[0], err[1]);
    return m;
}

void printList(std::ostream& out, const char* key, const std::vector<double>& values) {
    out << std::left << std::setw(24) << key << "(";
    for (std::size_t i = 0; i < values.size(); ++i) out << (i ? " " : "") << values[i];
    out << ");\n";
}

// The friction of setting i, read from both of its cases, whose keys must match the first case's.
double settingFriction(const HydrodynamicWallInput& in, std::size_t i, SlipCalibrationKey& key, std::string& keyCase) {
    double gammaL = 0.0;
    for (const std::string& dir : {in.couette[i], in.poiseuille[i]}) {
        if (!std::filesystem::is_directory(dir))
            throw std::invalid_argument(dir + ": a calibration reads the runs' cases, not their fit.dat files");
        const CalibrationCase c = readCalibrationCase(dir);
        if (keyCase.empty()) { key = c.key; keyCase = dir; }
        const std::string difference = c.key.firstDifference(key);
        if (!difference.empty())
            throw std::invalid_argument(dir + ": not the fluid and wall model of " + keyCase + " (" + difference + ")");
        if (dir != in.couette[i] && c.gammaL != gammaL)
            throw std::invalid_argument(dir + ": gammaL " + std::to_string(c.gammaL) + ", its Couette run's " + std::to_string(gammaL));
        gammaL = c.gammaL;
    }
    return gammaL;
}

// The sweep's slip calibration, written to in.calibration.
void writeCalibration(const HydrodynamicWallInput& in, const HydrodynamicWallFit& fit) {
    SlipCalibrationKey key;
    std::string keyCase;
    std::vector<SlipCalibrationPoint> points;
    for (std::size_t i = 0; i < in.couette.size(); ++i)
        points.push_back({settingFriction(in, i, key, keyCase), fit.slipLength[i], fit.slipLengthErr[i]});
    const SlipCalibration calibration(key, points, fit.offset, fit.halfWidthErr,
                                      "hydrodynamicWall, " + std::to_string(points.size()) + " frictions from " + keyCase +
                                          " and its sweep");
    Dictionary d(in.calibration);
    calibration.writeTo(d);
    writeDictionaryFile(in.calibration, d);
}

}  // namespace

void printHydrodynamicWall(const HydrodynamicWallInput& in, std::ostream& out) {
    if (in.couette.size() != in.poiseuille.size())
        throw std::invalid_argument(std::to_string(in.couette.size()) + " Couette runs and " +
                                    std::to_string(in.poiseuille.size()) + " Poiseuille runs: give one of each per setting");
    std::vector<ApparentSlip> settings;
    double width = 0.0;
    std::string widthFile;
    for (std::size_t i = 0; i < in.couette.size(); ++i) {
        const WallsMean c = readFit(in.couette[i], "couette"), p = readFit(in.poiseuille[i], "poiseuille");
        for (const WallsMean* m : {&c, &p}) {
            if (widthFile.empty()) { width = m->width; widthFile = m->file; }
            if (std::abs(m->width - width) > 1e-9 * width)
                throw IoError(m->file + ": the walls are " + std::to_string(m->width) + " apart, in " + widthFile + " " +
                              std::to_string(width) + ": the settings must share one channel");
        }
        settings.push_back({c.slip, c.slipErr, p.slip, p.slipErr});
    }
    const HydrodynamicWallFit fit = fitHydrodynamicWall(width, settings);
    if (!in.calibration.empty()) writeCalibration(in, fit);  // refused before anything is printed
    out << std::setprecision(8) << std::left;
    out << std::setw(24) << "width" << width << ";\n"
        << std::setw(24) << "halfWidth" << fit.halfWidth << ";\n"
        << std::setw(24) << "halfWidthError" << fit.halfWidthErr << ";\n"
        << std::setw(24) << "offset" << fit.offset << ";\n"
        << std::setw(24) << "chi2PerDof" << fit.chi2PerDof << ";\n"
        << std::setw(24) << "dof" << fit.dof << ";\n";
    const auto column = [&](double ApparentSlip::*member) {
        std::vector<double> values;
        for (const ApparentSlip& s : settings) values.push_back(s.*member);
        return values;
    };
    printList(out, "apparentSlipCouette", column(&ApparentSlip::couette));
    printList(out, "apparentSlipCouetteError", column(&ApparentSlip::couetteErr));
    printList(out, "apparentSlipPoiseuille", column(&ApparentSlip::poiseuille));
    printList(out, "apparentSlipPoiseuilleError", column(&ApparentSlip::poiseuilleErr));
    printList(out, "slipLength", fit.slipLength);
    printList(out, "slipLengthError", fit.slipLengthErr);
    if (!in.calibration.empty()) out << std::setw(24) << "calibration" << '"' << in.calibration << "\";\n";
}

}  // namespace dpd
