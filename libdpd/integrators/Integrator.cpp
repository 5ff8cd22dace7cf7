#include "integrators/Integrator.hpp"

namespace dpd {

std::vector<std::string> integratorTypes() { return integratorRegistry().names(); }

std::string integratorTypeList() { return integratorRegistry().nameList(); }

IntegratorSettings IntegratorSettings::read(const Dictionary& sub) {
    IntegratorSettings s;
    s.type = sub.get<std::string>("type");
    if (!integratorRegistry().has(s.type))
        sub.fail("type", "unknown integrator '" + s.type + "': expected " + integratorTypeList());
    s.coeffs = sub;
    makeIntegrator(s);  // the type checks its own keywords and values now, not at the first step
    return s;
}

IntegratorSettings IntegratorSettings::parse(const std::string& text) {
    return read(Dictionary::parse(text, "integrator"));
}

std::unique_ptr<Integrator> makeIntegrator(const IntegratorSettings& s) {
    return integratorRegistry().make(s.type, s.coeffs);
}

}  // namespace dpd
