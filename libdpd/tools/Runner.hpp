#pragma once
// The time loop of dpdFoamLike: reads the case, runs it, reports progress in an OpenFOAM-style log,
// writes time directories, and stops cleanly (last good state written) when the run goes unstable.
#include <iosfwd>
#include <string>

namespace dpd {

// Runs the case. Input errors (InputError, IoError) are thrown before anything is written;
// an unstable run writes its last good state and throws InstabilityError.
void runCase(const std::string& caseDir, std::ostream& log);

}  // namespace dpd
