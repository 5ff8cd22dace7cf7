#include "sampling/FunctionObjects.hpp"

#include "io/Dictionary.hpp"

namespace dpd {

FunctionObjects::FunctionObjects(const FunctionObjects& other) {
    for (const auto& f : other.functions_) functions_.push_back(f->clone());
}

FunctionObjects& FunctionObjects::operator=(const FunctionObjects& other) {
    if (this != &other) *this = FunctionObjects(other);
    return *this;
}

FunctionObjects FunctionObjects::read(const Dictionary& functions, const System& sys) {
    FunctionObjects out;
    for (const std::string& name : functions.keys()) {
        if (!functions.isDict(name)) functions.fail(name, "each function object is a sub-dictionary");
        const Dictionary& d = functions.subDict(name);
        const std::string type = d.get<std::string>("type");
        if (!functionObjectTypes().has(type))
            d.fail("type", "unknown function object type '" + type + "' (expected " + functionObjectTypes().nameList() + ")");
        out.functions_.push_back(functionObjectTypes().make(type, d, name, sys));
    }
    return out;
}

void FunctionObjects::execute(const System& sys) {
    for (auto& f : functions_) f->execute(sys);
}

void FunctionObjects::write(const std::string& timeDir, const System& sys) const {
    for (const auto& f : functions_) f->write(timeDir, sys);
}

FunctionObjects FunctionObjects::summedOverRanks(const Communicator& comm) const {
    FunctionObjects out(*this);
    for (auto& f : out.functions_) f->sumOverRanks(comm);
    return out;
}

void FunctionObjects::keepRestoredSums(bool keep) {
    for (auto& f : functions_) f->keepRestoredSums(keep);
}

void FunctionObjects::restore(const std::string& timeDir) {
    for (auto& f : functions_) f->restore(timeDir);
}

}  // namespace dpd
