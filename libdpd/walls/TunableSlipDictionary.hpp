#pragma once
// A wall's tunable-slip layer as its dictionary gives it (docs/walls.md 3.5), and a wall's `slipLength`
// resolved against the case's slip calibration (3.8): read alike for a plane and for a geometry.
#include "walls/SlipLengthResolver.hpp"
#include "walls/TunableSlipParameters.hpp"

#include <string>

namespace dpd {

class Dictionary;
struct WallReadContext;

// tunableSlip { gammaL 2; zc 1; epsilon 1; sigma 0.5; } (docs/walls.md 3.5): all four are needed;
// friction all (default) | tangential; fluidBehind { a 25; density 3; } (optional; density 0 is none).
// A wall that asks for a slip length gives the model alone: its gammaL comes from the calibration.
// Stripes are the planar wall's to read (the key is allowed here).
TunableSlipParameters readTunableSlip(const Dictionary& td, double cutoff, bool asksSlipLength);

// A wall that asks for a slip length gives its model (the tunableSlip block, without gammaL): an
// InputError on its slipLength keyword otherwise.
void requireSlipModel(const Dictionary& wd);

// The friction and the offset behind the wall's surface that give the slip length b of a wall of this
// model (its gammaL unused), from the case's calibration (c.slipLengths); the choice is added to the
// log's notes. A failure is an InputError on the wall's slipLength keyword.
CalibratedWall resolveSlipLength(const Dictionary& wd, const WallReadContext& c, const TunableSlipParameters& model,
                                 double b);

}  // namespace dpd
