#pragma once
// The instantaneous scalar pressure of a periodic system, for the integrator speed-accuracy study:
//   P = ( sum_i m v_i^2 + sum_{i<j} r_ij . F_ij ) / (d V),
// the kinetic part over the mobile particles (masses 1) plus the pair virial, both summed over the
// d active axes (x and z in 2-D). The virial is that of sampling/PairVirial (conservative and
// dissipative forces; the random force's virial averages to zero and is left out), taken as one bin
// spanning the box, so every pair counts once whole. The kinetic part is about zero velocity: use it
// for a fluid at rest (no mean flow).
namespace dpd {

class System;

// The particles must be sorted by the system's cell list (as they are after a step).
double instantaneousPressure(const System& sys);

}  // namespace dpd
