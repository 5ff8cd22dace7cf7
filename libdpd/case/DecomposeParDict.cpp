#include "case/DecomposeParDict.hpp"

#include "core/Box.hpp"
#include "neighbour/CellList.hpp"
#include "parallel/SlabDecomposition.hpp"

#include <filesystem>
#include <numeric>

namespace dpd {

DecomposeSettings readDecomposeParDict(const std::string& caseDir, int ranks) {
    DecomposeSettings s;
    const auto path = std::filesystem::path(caseDir) / "system" / "decomposeParDict";
    if (!std::filesystem::exists(path)) return s;
    s.dict = Dictionary::readFile(path.string());
    s.present = true;
    s.dict.checkKeys({"numberOfSubdomains", "method", "planes"});
    const int subdomains = s.dict.get<int>("numberOfSubdomains");
    if (subdomains != ranks)
        s.dict.fail("numberOfSubdomains", std::to_string(subdomains) + " subdomains, but the run has " + std::to_string(ranks) +
                                              " ranks (mpirun -np " + std::to_string(subdomains) + ")");
    const std::string method = s.dict.getOrDefault("method", "slabs");
    if (method != "slabs") s.dict.fail("method", "unknown method '" + method + "' (expected slabs)");
    if (s.dict.found("planes")) {
        s.planes = s.dict.get<std::vector<int>>("planes");
        if (static_cast<int>(s.planes.size()) != ranks)
            s.dict.fail("planes", std::to_string(s.planes.size()) + " entries for " + std::to_string(ranks) + " ranks");
    }
    return s;
}

void checkPlanesFitBox(const DecomposeSettings& s, const Box& box, double cutoff, double ghostReach) {
    if (s.planes.empty()) return;
    CellList grid;
    grid.setup(box, cutoff);
    const int planes = grid.cellsPerAxis()[0];
    const int total = std::accumulate(s.planes.begin(), s.planes.end(), 0);
    if (total != planes)
        s.dict.fail("planes", "they add up to " + std::to_string(total) + ", but the box has " + std::to_string(planes) +
                                  " planes of cells along x");
    const int ranks = static_cast<int>(s.planes.size());
    const int ghosts = SlabDecomposition::ghostPlanesFor(ghostReach, grid.cellSize().x());
    const int least = SlabDecomposition::minPlanes(ranks, ghosts);
    for (int n : s.planes)
        if (n < least)
            s.dict.fail("planes", "each of " + std::to_string(ranks) + " ranks needs at least " + std::to_string(least) +
                                      " planes (the " + std::to_string(ghosts) + " ghost plane" + (ghosts > 1 ? "s" : "") +
                                      " on either side of a rank are its neighbours'" +
                                      (ghosts > 1 ? ", as many as a bond reaches" : "") + ")");
}

}  // namespace dpd
