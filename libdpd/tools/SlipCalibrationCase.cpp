#include "tools/SlipCalibrationCase.hpp"

#include "case/DpdProperties.hpp"
#include "io/Dictionary.hpp"

#include <filesystem>

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
    namespace fs = std::filesystem;
    const Dictionary properties = Dictionary::readFile((fs::path(caseDir) / "constant" / "dpdProperties").string());
    const DpdModel m = readDpdModel(properties);
    CalibrationCase c;
    const int fluid = mobileSpecies(m, properties);
    const PairCoeffs& pair = m.pairs(fluid, fluid);
    c.key.a = pair.a;
    c.key.gamma = pair.gamma;
    c.key.kT = m.kT;
    c.key.cutoff = m.cutoff;
    c.key.dimension = m.dimension;
    c.key.integrator = makeIntegrator(m.integrator)->description();
    const TunableSlipParameters& wall = sharedWallModel(m, properties);
    c.key.setWallModel(wall);
    c.gammaL = wall.gammaL;
    const Dictionary control = Dictionary::readFile((fs::path(caseDir) / "system" / "controlDict").string());
    c.key.dt = control.getPositive<double>("deltaT");
    const Dictionary builder = Dictionary::readFile((fs::path(caseDir) / "system" / "blockFrozenWallDict").string());
    c.key.density = builder.subDict("fluid").getPositive<double>("density");
    return c;
}

}  // namespace dpd
