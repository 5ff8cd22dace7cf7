#include "integrators/Integrator.hpp"

#include "integrators/DpdVvIntegrator.hpp"
#include "integrators/EulerIntegrator.hpp"
#include "integrators/GrootWarrenIntegrator.hpp"
#include "integrators/ShardlowIntegrator.hpp"

#include <stdexcept>

namespace dpd {

const std::vector<std::string>& integratorTypes() {
    static const std::vector<std::string> types{"Euler", "GrootWarren", "DPDVV", "Shardlow"};
    return types;
}

std::string integratorTypeList() {
    const auto& types = integratorTypes();
    std::string list;
    for (std::size_t k = 0; k < types.size(); ++k)
        list += (k == 0 ? "" : (k + 1 == types.size() ? " or " : ", ")) + types[k];
    return list;
}

std::unique_ptr<Integrator> makeIntegrator(const IntegratorSettings& s) {
    if (s.type == "Euler") return std::make_unique<EulerIntegrator>();
    if (s.type == "GrootWarren") {
        if (s.lambda < 0.0 || s.lambda > 1.0) throw std::invalid_argument("lambda must lie in [0, 1]");
        return std::make_unique<GrootWarrenIntegrator>(s.lambda);
    }
    if (s.type == "DPDVV") return std::make_unique<DpdVvIntegrator>();
    if (s.type == "Shardlow") return std::make_unique<ShardlowIntegrator>();
    throw std::invalid_argument("unknown integrator '" + s.type + "' (expected " + integratorTypeList() + ")");
}

}  // namespace dpd
