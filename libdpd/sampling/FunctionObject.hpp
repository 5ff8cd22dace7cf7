#pragma once
// A run-time function object of controlDict's `functions` (as OpenFOAM's): made by name from its
// sub-dictionary, it samples after the steps it wants, writes what it holds at each write time, and
// carries its sums on across a restart. Adding a type adds its files and one line in
// sampling/FunctionObjectTypes.cpp.
#include "core/Capabilities.hpp"
#include "core/Registry.hpp"

#include <memory>
#include <string>

namespace dpd {

class Communicator;
class Dictionary;
class System;

class FunctionObject {
public:
    virtual ~FunctionObject() = default;
    virtual std::unique_ptr<FunctionObject> clone() const = 0;
    virtual const std::string& name() const = 0;
    // Samples whatever is due after the step the system has just made.
    virtual void execute(const System& sys) = 0;
    // Writes what it holds under <timeDir>/ (nothing before its first sample).
    virtual void write(const std::string& timeDir, const System& sys) const = 0;
    // Carries on from what it wrote under <timeDir>/ before a restart (nothing there is fine).
    virtual void restore(const std::string& timeDir) = 0;
    // What it cannot sample beside (core/Capabilities.hpp), checked once before the first step. A type
    // that samples a run decomposed over several ranks says so by leaving out the refusal of several
    // ranks: each rank samples its own particles, sumOverRanks adds them (on every rank, before the
    // first writes), and the sums restored from a time directory count once (keepRestoredSums is false
    // on all ranks but the first).
    virtual Capabilities capabilities() const = 0;
    virtual void sumOverRanks(const Communicator&) {}
    virtual void keepRestoredSums(bool) {}
};

// Makers take the function's sub-dictionary, its name and the system it samples.
using FunctionObjectRegistry = Registry<FunctionObject, const Dictionary&, const std::string&, const System&>;
const FunctionObjectRegistry& functionObjectTypes();

}  // namespace dpd
