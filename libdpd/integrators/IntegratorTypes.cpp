// The integrator types a case can name: one line per type.
#include "integrators/DpdVvIntegrator.hpp"
#include "integrators/EulerIntegrator.hpp"
#include "integrators/GrootWarrenIntegrator.hpp"
#include "integrators/ShardlowIntegrator.hpp"

namespace dpd {

const IntegratorRegistry& integratorRegistry() {
    static const IntegratorRegistry types = [] {
        IntegratorRegistry r;
        r.add("Euler", &EulerIntegrator::New);
        r.add("GrootWarren", &GrootWarrenIntegrator::New);
        r.add("DPDVV", &DpdVvIntegrator::New);
        r.add("Shardlow", &ShardlowIntegrator::New);
        return r;
    }();
    return types;
}

}  // namespace dpd
