#pragma once
// DPD-VV (Besold, Vattulainen, Karttunen and Polson, Phys. Rev. E 62, R7611, 2000): velocity Verlet in
// which the dissipative force is evaluated once more at the end of the step, with the final velocities,
// so that the next half kick uses a dissipative force consistent with the velocities it acts on:
//   v'       = v + dt f / 2
//   r(t+dt)  = r + dt v'
//   f'       = f^C(r(t+dt)) + f^R(r(t+dt)) + f^D(r(t+dt), v')
//   v(t+dt)  = v' + dt f' / 2
//   f(t+dt)  = f' - f^D(r(t+dt), v') + f^D(r(t+dt), v(t+dt))
// The dissipative force is linear in the velocities, so the last line is f' + f^D(v(t+dt) - v') with
// v(t+dt) - v' = dt f' / 2: one extra pair loop of the dissipative term alone.
#include "integrators/Integrator.hpp"

#include <vector>

namespace dpd {

class DpdVvIntegrator : public Integrator {
public:
    // No coefficients.
    static std::unique_ptr<Integrator> New(const Dictionary& coeffs);
    std::string name() const override { return "DPDVV"; }
    // It computes the pair force in parts, and the bonded pairs' share is taken back from the whole.
    Capabilities capabilities() const override {
        return {{}, {{{Feature::pairForceTakenBack}, "cannot take back part of the pair force (it computes the pair force in parts)", ""}}};
    }
    WallCounters step(System& sys) override;

private:
    // Velocities and forces kept aside while the dissipative correction is computed.
    std::vector<double> vx_, vy_, vz_, fx_, fy_, fz_;
};

}  // namespace dpd
