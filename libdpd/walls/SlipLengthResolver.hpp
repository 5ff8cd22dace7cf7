#pragma once
// How a planar wall that asks for a slip length (`slipLength b;`, docs/walls.md 3.8) gets the friction
// and plane that give it: a resolver looks up the calibration of the case's fluid and of the wall's
// model (walls/SlipCalibration.hpp). The walls layer asks; the case layer, which knows the case's
// files, answers (case/CaseSlipCalibrations.hpp).
#include "walls/TunableSlipParameters.hpp"

#include <string>

namespace dpd {

// What a calibration chose for an asked slip length.
struct CalibratedWall {
    double gammaL = 0.0;
    // The plane lies this far behind where the user put the wall, so that the hydrodynamic wall (where
    // the calibration found the wall acts) is there.
    double planeOffset = 0.0;
    std::string note;  // for the log: what was chosen, from which calibration, with its errors
};

class SlipLengthResolver {
public:
    virtual ~SlipLengthResolver() = default;
    // The wall for slip length b of a wall of this model (its gammaL unused). Throws
    // std::runtime_error (no calibration matches) or std::out_of_range (b outside the calibrated
    // range), the message naming what to run.
    virtual CalibratedWall resolve(const TunableSlipParameters& wallModel, double slipLength) const = 0;
};

}  // namespace dpd
