#include "integrators/Integrator.hpp"

#include "integrators/EulerIntegrator.hpp"
#include "integrators/GrootWarrenIntegrator.hpp"

#include <stdexcept>

namespace dpd {

std::unique_ptr<Integrator> makeIntegrator(const IntegratorSettings& s) {
    if (s.type == "Euler") return std::make_unique<EulerIntegrator>();
    if (s.type == "GrootWarren") {
        if (s.lambda < 0.0 || s.lambda > 1.0) throw std::invalid_argument("lambda must lie in [0, 1]");
        return std::make_unique<GrootWarrenIntegrator>(s.lambda);
    }
    throw std::invalid_argument("unknown integrator '" + s.type + "' (expected Euler or GrootWarren)");
}

}  // namespace dpd
