#pragma once
// A time integrator advances a System by one step. On entry the forces are those of the current
// state; on exit the clock has moved on by dt and the forces are those of the new state.
//
// Types are chosen by name (integrator { type <name>; <its coefficients> } in dpdProperties): each
// type makes itself from its sub-dictionary, reading and checking its own keys, and says which scenes
// it cannot run. Adding a type adds its files and one line in integrators/IntegratorTypes.cpp.
#include "core/Capabilities.hpp"
#include "core/Registry.hpp"
#include "io/Dictionary.hpp"
#include "walls/WallList.hpp"

#include <memory>
#include <string>
#include <vector>

namespace dpd {

class System;

class Integrator {
public:
    virtual ~Integrator() = default;
    virtual std::string name() const = 0;
    // The type with the coefficients that change its trajectories, defaults included, as words
    // ("GrootWarren lambda 0.65"): what a calibration made with it must match.
    virtual std::string description() const { return name(); }
    // Returns what the walls did during the step.
    virtual WallCounters step(System& sys) = 0;
    // What the scheme cannot run beside (core/Capabilities.hpp), checked once before the first step.
    // Several ranks take only what every particle does alone between one pair loop and the next (a
    // sequential sweep would need the neighbours' updates).
    virtual Capabilities capabilities() const = 0;
};

using IntegratorRegistry = Registry<Integrator, const Dictionary&>;
// The integrator types, in the order they are listed to users.
const IntegratorRegistry& integratorRegistry();
// Their names, and the same as text ("Euler, ... or Shardlow").
std::vector<std::string> integratorTypes();
std::string integratorTypeList();

// What a case says of its integrator: the type and its sub-dictionary (the type's coefficients).
struct IntegratorSettings {
    std::string type = "GrootWarren";
    Dictionary coeffs{"integrator"};

    // From a sub-dictionary { type <name>; ... }: an InputError naming the file, line and keyword for
    // an unknown type or a coefficient the type does not take or accept.
    static IntegratorSettings read(const Dictionary& sub);
    // The same from text, e.g. "type GrootWarren; lambda 0.5;".
    static IntegratorSettings parse(const std::string& text);
};

// Throws std::invalid_argument for an unknown type, InputError for bad coefficients.
std::unique_ptr<Integrator> makeIntegrator(const IntegratorSettings& s);

}  // namespace dpd
