#include "tools/InsertChainsTool.hpp"

#include "case/DpdProperties.hpp"
#include "core/Error.hpp"
#include "io/Dictionary.hpp"
#include "system/System.hpp"

#include <filesystem>
#include <limits>
#include <ostream>

namespace dpd {

ChainReport runInsertChains(const std::string& caseDir, std::ostream& out) {
    namespace fs = std::filesystem;
    const DpdModel model = readDpdProperties(caseDir);
    const std::string dictFile = (fs::path(caseDir) / "system" / "insertChainsDict").string();
    const Dictionary dict = Dictionary::readFile(dictFile);
    if (!model.bondPotential)
        throw IoError((fs::path(caseDir) / "constant" / "dpdProperties").string() +
                      ": chains need a bonds block (e.g. bonds { type FENE; H 6; rMax 3; })");
    const ChainSettings settings = ChainSettings::read(dict, model.kT);
    if (model.species.indexOf(settings.beadSpecies) < 0 || model.species[model.species.indexOf(settings.beadSpecies)].frozen)
        dict.fail("species", "'" + settings.beadSpecies + "' must be a mobile species of constant/dpdProperties");
    const std::string file = (fs::path(caseDir) / "0" / snapshotFileName).string();
    Snapshot snapshot = readSnapshot(file);
    // The run's own walls (the time step does not matter here).
    const System walls = buildSystem(model, snapshot, 0.01, file);
    const ClearanceFunction clearance = [&](const Eigen::Vector3d& r) {
        double nearest = std::numeric_limits<double>::infinity();
        for (std::size_t w = 0; w < walls.walls.size(); ++w) nearest = std::min(nearest, walls.walls[w].signedDistance(r));
        return nearest;
    };
    ChainReport report;
    try {
        report = insertChains(snapshot, settings, *model.bondPotential, clearance);
    } catch (const std::invalid_argument& e) {
        throw IoError(dictFile + ": " + e.what());
    }
    writeSnapshot((fs::path(caseDir) / "0").string(), snapshot);
    out << "Chains           : " << settings.chains << " of " << settings.length << " beads ("
        << model.bondPotential->description() << ")\n"
        << "Beads            : " << report.beads << " fluid particles of species '" << settings.fluidSpecies
        << "' became '" << settings.beadSpecies << "' (farthest moved " << report.largestMove << ")\n"
        << "Mean bond length : " << report.meanBondLength << "\n"
        << "Walks restarted  : " << report.restarts << "\n"
        << "Written " << file << "\n";
    return report;
}

}  // namespace dpd
