#pragma once
// The explicit Euler scheme of the original DPD papers (Hoogerbrugge & Koelman 1992): positions with
// the old velocities, velocities with the old forces. Poor (kT drifts with dt); kept for comparison.
#include "integrators/Integrator.hpp"

namespace dpd {

class EulerIntegrator : public Integrator {
public:
    // No coefficients.
    static std::unique_ptr<Integrator> New(const Dictionary& coeffs);
    std::string name() const override { return "Euler"; }
    Capabilities capabilities() const override { return {}; }
    WallCounters step(System& sys) override;
};

}  // namespace dpd
