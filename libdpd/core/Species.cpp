#include "core/Species.hpp"

#include <stdexcept>

namespace dpd {

int SpeciesTable::add(const Species& s) {
    if (indexOf(s.name) >= 0) throw std::invalid_argument("species '" + s.name + "' defined twice");
    species_.push_back(s);
    return size() - 1;
}

int SpeciesTable::indexOf(const std::string& name) const {
    for (int i = 0; i < size(); ++i)
        if (species_[i].name == name) return i;
    return -1;
}

std::vector<std::string> SpeciesTable::names() const {
    std::vector<std::string> out;
    for (const auto& s : species_) out.push_back(s.name);
    return out;
}

bool PairTable::anyConservative() const {
    for (const auto& p : c_)
        if (p.interact && p.a != 0.0) return true;
    return false;
}

}  // namespace dpd
