#pragma once
// The run-time function objects declared in controlDict's `functions` (sampling/FunctionObject.hpp;
// the types: sampling/FunctionObjectTypes.cpp, so far binnedProfile, sampling/BinnedProfile.hpp).
#include "sampling/FunctionObject.hpp"

#include <memory>
#include <string>
#include <vector>

namespace dpd {

class FunctionObjects {
public:
    FunctionObjects() = default;
    FunctionObjects(const FunctionObjects& other);
    FunctionObjects& operator=(const FunctionObjects& other);
    FunctionObjects(FunctionObjects&&) = default;
    FunctionObjects& operator=(FunctionObjects&&) = default;

    // Reads and checks every entry; errors name controlDict, the line and the keyword.
    static FunctionObjects read(const Dictionary& functions, const System& sys);
    // Samples whatever is due after the step the system has just made.
    void execute(const System& sys);
    // Writes every function's results under <timeDir>/.
    void write(const std::string& timeDir, const System& sys) const;
    // Carries sums accumulated before a restart on from <timeDir>/ (missing files are fine).
    void restore(const std::string& timeDir);
    std::size_t size() const { return functions_.size(); }

private:
    std::vector<std::unique_ptr<FunctionObject>> functions_;
};

}  // namespace dpd
