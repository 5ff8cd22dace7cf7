#pragma once
// Species and the per-pair DPD coefficients.
#include <string>
#include <vector>

namespace dpd {

struct Species {
    std::string name;
    bool frozen = false;  // frozen particles never move on their own and never interact with each other
};

struct PairCoeffs {
    double a = 0.0;      // conservative amplitude
    double gamma = 0.0;  // dissipative coefficient
    double sigma = 0.0;  // random amplitude, sqrt(2 gamma kT) by fluctuation-dissipation
    bool interact = true;
};

class SpeciesTable {
public:
    int add(const Species& s);  // returns the index; names must be unique
    int size() const { return static_cast<int>(species_.size()); }
    const Species& operator[](int i) const { return species_[i]; }
    int indexOf(const std::string& name) const;  // -1 when unknown
    std::vector<std::string> names() const;

private:
    std::vector<Species> species_;
};

// Symmetric table of pair coefficients, indexed by two species indices.
class PairTable {
public:
    PairTable() = default;
    explicit PairTable(int nSpecies) : n_(nSpecies), c_(nSpecies * nSpecies) {}
    int nSpecies() const { return n_; }
    const PairCoeffs& operator()(int i, int j) const { return c_[i * n_ + j]; }
    void set(int i, int j, const PairCoeffs& p) { c_[i * n_ + j] = p; c_[j * n_ + i] = p; }
    bool anyConservative() const;

private:
    int n_ = 0;
    std::vector<PairCoeffs> c_;
};

}  // namespace dpd
