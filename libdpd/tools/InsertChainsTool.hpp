#pragma once
// insertChains: puts polymer chains into a built case (setup/ChainBuilder.hpp): reads
// system/insertChainsDict and constant/dpdProperties (the bonds block gives the spring), takes the
// snapshot of time 0 as blockFrozenWall or randomEquilWall wrote it, and writes it back with the chains.
// The beads keep clear of every wall the run will have (planar walls and the geometry's solid).
#include "setup/ChainBuilder.hpp"

#include <iosfwd>
#include <string>

namespace dpd {

ChainReport runInsertChains(const std::string& caseDir, std::ostream& out);

}  // namespace dpd
