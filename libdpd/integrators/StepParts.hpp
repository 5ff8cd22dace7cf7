#pragma once
// The parts the integrators' steps are made of.
#include "neighbour/CellList.hpp"
#include "walls/WallList.hpp"

namespace dpd {

class System;

// v += h f for every mobile particle (frozen particles keep their velocity).
void kick(System& sys, double h);

// r += dt v for every particle (frozen ones carry their wall velocity).
void drift(System& sys);

// v += dt f / 2 (mobile particles), then r += dt v: the first half of a velocity-Verlet step.
void halfKickAndDrift(System& sys);

// After the particles moved: the clock moves on one step, walls reflect the particles that crossed
// them, positions are wrapped into the box and the particles sorted by cell, ready for new forces;
// the sort moves the forces along, or leaves them behind for a step whose System::computeForces()
// writes over them (System::sortByCell). Returns what the walls did.
WallCounters endMove(System& sys, SortForces forces);

}  // namespace dpd
