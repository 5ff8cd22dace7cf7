#include "tools/SlipCalibrationCase.hpp"

#include "case/CaseSlipCalibrations.hpp"
#include "case/DpdProperties.hpp"
#include "io/Dictionary.hpp"

#include <filesystem>

namespace dpd {

namespace {

// The walls' shared model and friction (both walls: planar, tunable slip, no stripes, alike).
const TunableSlipParameters& sharedWallModel(const DpdModel& m, const Dictionary& properties) {
    if (m.planarWalls.empty() || m.planarWalls.size() != m.walls.size())
        properties.fail("walls", "a slip calibration's walls are planar tunable-slip walls, and only those");
    const PlanarWallSettings& first = m.planarWalls.front();
    for (const PlanarWallSettings& w : m.planarWalls) {
        const std::string where = "walls/" + w.name;
        if (!w.hasTunableSlip) properties.fail(where, "is not a tunable-slip wall: a slip calibration sweeps their friction");
        if (w.hasStripes) properties.fail(where + "/tunableSlip/stripes", "a slip calibration's walls are uniform");
        SlipCalibrationKey mine, theirs;
        mine.setWallModel(w.tunableSlip);
        theirs.setWallModel(first.tunableSlip);
        const std::string difference = mine.firstDifference(theirs);
        if (!difference.empty() || w.tunableSlip.gammaL != first.tunableSlip.gammaL)
            properties.fail(where + "/tunableSlip", "differs from wall " + first.name +
                                                        (difference.empty() ? " in gammaL" : ": " + difference));
    }
    return first.tunableSlip;
}

}  // namespace

CalibrationCase readCalibrationCase(const std::string& caseDir) {
    const Dictionary properties =
        Dictionary::readFile((std::filesystem::path(caseDir) / "constant" / "dpdProperties").string());
    const DpdModel m = readDpdModel(properties);
    CalibrationCase c;
    c.key = slipCalibrationFluid(m, properties, caseDir);
    const TunableSlipParameters& wall = sharedWallModel(m, properties);
    c.key.setWallModel(wall);
    c.gammaL = wall.gammaL;
    return c;
}

}  // namespace dpd
