#pragma once
// Groot & Warren's modified velocity Verlet (J. Chem. Phys. 107, 4423, 1997):
//   r(t+dt) = r + dt v + dt^2 f / 2
//   v~      = v + lambda dt f                 (predicted velocity for the dissipative force)
//   f(t+dt) = f(r(t+dt), v~)
//   v(t+dt) = v + dt (f + f(t+dt)) / 2
// lambda = 0.5 is plain velocity Verlet; 0.65 is the usual choice.
//
// After the drift, v holds v + dt f / 2 and v~ is that plus (lambda - 1/2) dt f. The pair loop makes
// v~ itself as it reads the velocities (ForcePass::predictorShift), so v + dt f / 2 stays in v and
// the step ends with one more half kick: no pass of its own for the prediction and no copy of v.
// Where other forces depend on the velocities (tunable-slip walls) they must see v~ too: there v~ is
// written into v for the force computation and v + dt f / 2 kept aside.
#include "integrators/Integrator.hpp"

#include <vector>

namespace dpd {

class GrootWarrenIntegrator : public Integrator {
public:
    explicit GrootWarrenIntegrator(double lambda) : lambda_(lambda) {}
    // lambda (default 0.65) in [0, 1].
    static std::unique_ptr<Integrator> New(const Dictionary& coeffs);
    std::string name() const override { return "GrootWarren"; }
    std::string description() const override;
    double lambda() const { return lambda_; }
    Capabilities capabilities() const override { return {}; }
    WallCounters step(System& sys) override;
    // Bytes held by the integrator's own buffers.
    std::size_t memoryBytes() const { return sizeof(double) * (hx_.capacity() + hy_.capacity() + hz_.capacity()); }

private:
    double lambda_;
    std::vector<double> hx_, hy_, hz_;  // v + dt f / 2, kept aside where v must hold v~
};

}  // namespace dpd
