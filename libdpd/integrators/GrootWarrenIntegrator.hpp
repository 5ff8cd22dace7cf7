#pragma once
// Groot & Warren's modified velocity Verlet (J. Chem. Phys. 107, 4423, 1997):
//   r(t+dt) = r + dt v + dt^2 f / 2
//   v~      = v + lambda dt f                 (predicted velocity for the dissipative force)
//   f(t+dt) = f(r(t+dt), v~)
//   v(t+dt) = v + dt (f + f(t+dt)) / 2
// lambda = 0.5 is plain velocity Verlet; 0.65 is the usual choice.
#include "integrators/Integrator.hpp"

#include <vector>

namespace dpd {

class GrootWarrenIntegrator : public Integrator {
public:
    explicit GrootWarrenIntegrator(double lambda) : lambda_(lambda) {}
    std::string name() const override { return "GrootWarren"; }
    double lambda() const { return lambda_; }
    WallCounters step(System& sys) override;
    // Bytes held by the integrator's own buffers.
    std::size_t memoryBytes() const { return sizeof(double) * (hx_.capacity() + hy_.capacity() + hz_.capacity()); }

private:
    double lambda_;
    std::vector<double> hx_, hy_, hz_;  // v + dt f / 2, kept while the new forces are computed
};

}  // namespace dpd
