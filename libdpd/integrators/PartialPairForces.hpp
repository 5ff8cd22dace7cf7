#pragma once
// Parts of the DPD pair force on their own, for schemes that treat them apart: Shardlow's splitting
// integrates the conservative force by velocity Verlet and the dissipative and random parts pair by
// pair; DPD-VV re-evaluates the dissipative force with the velocities of the end of the step.
namespace dpd {

class System;

// Forces := conservative pair forces + body force at the current positions (no pair loop at all when
// every a is zero). Requires sortByCell() since the last move.
void computeConservativeForces(System& sys);

// Forces += dissipative pair forces of the current positions and velocities. Requires sortByCell()
// since the last move.
void addDissipativeForces(System& sys);

}  // namespace dpd
