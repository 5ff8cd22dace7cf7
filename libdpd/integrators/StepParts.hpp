#pragma once
// The parts the integrators' steps are made of.

namespace dpd {

class System;

// v += h f for every mobile particle (frozen particles keep their velocity).
void kick(System& sys, double h);

// r += dt v for every particle (frozen ones carry their wall velocity).
void drift(System& sys);

// v += dt f / 2 (mobile particles), then r += dt v: the first half of a velocity-Verlet step.
void halfKickAndDrift(System& sys);

}  // namespace dpd
