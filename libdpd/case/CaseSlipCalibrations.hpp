#pragma once
// The slip calibrations a case's walls are resolved against (docs/walls.md 3.8). A wall that asks for
// a slip length takes the calibration whose key is the case's: the fluid from constant/dpdProperties
// (the self pair of its one mobile species, kT, cutoff, dimension, the integrator with its
// coefficients) and system/blockFrozenWallDict (fluid/density), the step from system/controlDict
// (deltaT), the wall model from the wall's tunableSlip block. Calibrations are looked for in the
// case's constant/slipCalibration, then in the user's cache (walls/SlipCalibration.hpp).
#include "walls/SlipCalibration.hpp"
#include "walls/SlipLengthResolver.hpp"

#include <optional>
#include <string>

namespace dpd {

class Dictionary;
struct DpdModel;

// The fluid's and the step's entries of a calibration key (the wall model's left empty). `model` needs
// only its species, pairs, kT, cutoff, dimension and integrator read. InputError at the entry for a
// case with not exactly one mobile species; IoError/InputError for a missing controlDict deltaT or
// blockFrozenWallDict fluid/density.
SlipCalibrationKey slipCalibrationFluid(const DpdModel& model, const Dictionary& properties, const std::string& caseDir);

class CaseSlipCalibrations : public SlipLengthResolver {
public:
    // model and properties must outlive the resolver (the walls are read while the model is).
    CaseSlipCalibrations(const DpdModel& model, const Dictionary& properties, std::string caseDir);
    CalibratedWall resolve(const TunableSlipParameters& wallModel, double slipLength) const override;

private:
    // The fluid's and step's key, read from the case's files once for all its walls.
    const SlipCalibrationKey& fluidKey() const;

    const DpdModel& model_;
    const Dictionary& properties_;
    std::string caseDir_;
    mutable std::optional<SlipCalibrationKey> fluidKey_;
};

}  // namespace dpd
