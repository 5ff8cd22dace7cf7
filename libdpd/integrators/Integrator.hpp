#pragma once
// A time integrator advances a System by one step. On entry the forces are those of the current
// state; on exit the clock has moved on by dt and the forces are those of the new state.
#include "walls/WallSet.hpp"

#include <memory>
#include <string>
#include <vector>

namespace dpd {

class System;

class Integrator {
public:
    virtual ~Integrator() = default;
    virtual std::string name() const = 0;
    // Returns what the walls did during the step.
    virtual WallCounters step(System& sys) = 0;
};

struct IntegratorSettings {
    std::string type = "GrootWarren";  // one of integratorTypes()
    double lambda = 0.65;              // Groot-Warren only; 0.5 is velocity Verlet
};

// The valid types: Euler, GrootWarren, DPDVV, Shardlow; and the same as text ("Euler, ... or Shardlow").
const std::vector<std::string>& integratorTypes();
std::string integratorTypeList();

// Throws std::invalid_argument for an unknown type or a lambda outside [0, 1].
std::unique_ptr<Integrator> makeIntegrator(const IntegratorSettings& s);

}  // namespace dpd
