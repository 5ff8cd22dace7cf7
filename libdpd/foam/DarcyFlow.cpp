#include "foam/DarcyFlow.hpp"

#include <cmath>
#include <stdexcept>

namespace dpd {

namespace {

void requirePositive(double v, const char* what) {
    if (!(v > 0.0) || !std::isfinite(v)) throw std::invalid_argument(std::string("Darcy flow: ") + what + " must be positive");
}

void requireNonzero(double v, const char* what) {
    if (v == 0.0 || !std::isfinite(v)) throw std::invalid_argument(std::string("Darcy flow: ") + what + " must be finite and non-zero");
}

void setPermeability(DarcyFlow& d, double nu, double g) {
    d.permeability = nu * d.superficialVelocity / g;
    d.permeabilityErr = nu * d.superficialVelocityErr / g;
}

}  // namespace

DarcyFlow darcyFromCells(const BinnedCells& cells, double cellsPerBin, double nu, double g) {
    requirePositive(cellsPerBin, "the number of cells per bin");
    requirePositive(nu, "nu");
    requireNonzero(g, "g");
    double sum = 0.0, count = 0.0;
    for (std::size_t k = 0; k < cells.sum.size(); ++k) {
        sum += cells.sum[k];
        count += static_cast<double>(cells.cells[k]);
    }
    const double total = cellsPerBin * static_cast<double>(cells.sum.size());
    DarcyFlow d;
    d.porosity = count / total;
    d.superficialVelocity = sum / total;
    setPermeability(d, nu, g);
    return d;
}

DarcyFlow darcyFromBins(const std::vector<double>& density, const std::vector<double>& u, const std::vector<double>& uErr,
                        double fluidDensity, double nu, double g) {
    if (density.size() != u.size() || (!uErr.empty() && uErr.size() != u.size()) || u.empty())
        throw std::invalid_argument("Darcy flow: the density and velocity columns differ in length or are empty");
    requirePositive(fluidDensity, "the fluid density");
    requirePositive(nu, "nu");
    requireNonzero(g, "g");
    double mass = 0.0, momentum = 0.0, err2 = 0.0;
    for (std::size_t k = 0; k < u.size(); ++k) {
        mass += density[k];
        if (density[k] == 0.0) continue;   // an empty bin's velocity is undefined
        momentum += density[k] * u[k];
        if (!uErr.empty()) err2 += density[k] * density[k] * uErr[k] * uErr[k];
    }
    const double n = static_cast<double>(u.size()) * fluidDensity;
    DarcyFlow d;
    d.porosity = mass / n;
    d.superficialVelocity = momentum / n;
    d.superficialVelocityErr = std::sqrt(err2) / n;
    setPermeability(d, nu, g);
    return d;
}

}  // namespace dpd
