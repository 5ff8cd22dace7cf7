#include "case/CaseSlipCalibrations.hpp"

#include "case/DpdProperties.hpp"
#include "io/Dictionary.hpp"

#include <filesystem>
#include <sstream>
#include <stdexcept>

namespace dpd {

namespace {

// The one mobile species of the case.
int mobileSpecies(const DpdModel& m, const Dictionary& properties) {
    int found = -1;
    for (int s = 0; s < m.species.size(); ++s) {
        if (m.species[s].frozen) continue;
        if (found >= 0) properties.fail("species", "a slip calibration's fluid is one mobile species, this case has more");
        found = s;
    }
    if (found < 0) properties.fail("species", "a slip calibration needs a mobile species");
    return found;
}

const char* kHowToCalibrate =
    "to make one, run etc/calibrateWall (a Couette and a Poiseuille sweep of gammaL in this fluid and wall "
    "model, then hydrodynamicWall -calibration FILE on them; tutorials/channel/slipLength/Allrun uses it), then "
    "put FILE in the case's constant/slipCalibration or in the user's cache ($DPD_SLIP_CALIBRATIONS, else "
    "~/.cache/dpdFoamLike/slipCalibrations); the project's own are in $DPD_PROJECT_DIR/etc/slipCalibrations";

}  // namespace

SlipCalibrationKey slipCalibrationFluid(const DpdModel& m, const Dictionary& properties, const std::string& caseDir) {
    namespace fs = std::filesystem;
    SlipCalibrationKey key;
    const int fluid = mobileSpecies(m, properties);
    const PairCoeffs& pair = m.pairs(fluid, fluid);
    key.a = pair.a;
    key.gamma = pair.gamma;
    key.kT = m.kT;
    key.cutoff = m.cutoff;
    key.dimension = m.dimension;
    key.integrator = makeIntegrator(m.integrator)->description();
    key.dt = Dictionary::readFile((fs::path(caseDir) / "system" / "controlDict").string()).getPositive<double>("deltaT");
    // The fluid's density as the case's builder fills it: blockFrozenWall for planes, randomEquilWall
    // for a geometry.
    const fs::path system = fs::path(caseDir) / "system";
    const fs::path builderFile = fs::exists(system / "blockFrozenWallDict") || !fs::exists(system / "randomEquilWallDict")
                                     ? system / "blockFrozenWallDict" : system / "randomEquilWallDict";
    const Dictionary builder = Dictionary::readFile(builderFile.string());
    key.density = builder.subDict("fluid").getPositive<double>("density");
    return key;
}

CaseSlipCalibrations::CaseSlipCalibrations(const DpdModel& model, const Dictionary& properties, std::string caseDir)
    : model_(model), properties_(properties), caseDir_(std::move(caseDir)) {}

const SlipCalibrationKey& CaseSlipCalibrations::fluidKey() const {
    if (!fluidKey_) fluidKey_ = slipCalibrationFluid(model_, properties_, caseDir_);
    return *fluidKey_;
}

CalibratedWall CaseSlipCalibrations::resolve(const TunableSlipParameters& wallModel, double b) const {
    SlipCalibrationKey key = fluidKey();
    key.setWallModel(wallModel);
    SlipCalibration calibration = [&] {
        try {
            return findSlipCalibration(slipCalibrationFiles(caseDir_), key);
        } catch (const std::runtime_error& e) {
            throw std::runtime_error(std::string(e.what()) + "; " + kHowToCalibrate);
        }
    }();
    CalibratedFriction friction;
    try {
        friction = calibration.wallFor(b);
    } catch (const std::out_of_range& e) {
        throw std::out_of_range(std::string(e.what()) + ": ask within it, or calibrate more gammaL; " +
                                kHowToCalibrate);
    }
    CalibratedWall wall;
    wall.gammaL = friction.gammaL;
    wall.planeOffset = friction.planeOffset;
    std::ostringstream note;
    note << "slipLength " << b << " from " << calibration.source() << ": gammaL " << friction.gammaL << " (b +- "
         << friction.slipLengthError << " there), acting " << friction.planeOffset << " +- "
         << calibration.wallOffsetError() << " behind where the wall was put";
    if (b < calibration.smallestSlip())
        note << " (below the calibrated " << calibration.smallestSlip() << ": the stiffest wall, moved "
             << calibration.smallestSlip() - b << " out)";
    wall.note = note.str();
    return wall;
}

}  // namespace dpd
