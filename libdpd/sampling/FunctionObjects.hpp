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
    const FunctionObject& operator[](std::size_t k) const { return *functions_[k]; }
    // A copy whose sums are those of every rank together (call on every rank of a decomposed run).
    FunctionObjects summedOverRanks(const Communicator& comm) const;
    // After restore(): whether this rank keeps the sums read back (only the first rank of a decomposed run does).
    void keepRestoredSums(bool keep);

private:
    std::vector<std::unique_ptr<FunctionObject>> functions_;
};

}  // namespace dpd
