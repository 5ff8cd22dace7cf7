#pragma once
// chainScaling: the Flory exponent of single chains from a sweep of cases, one chain length each
// (tutorials/polymer/scaling; docs/polymers.md). Per case: the chain length (system/insertChainsDict,
// `length`) and the mean <R_g^2> and <R_ee^2> with their block errors from the latest
// postProcessing/<function>/<time>/chainStatistics.dat (sampling/ChainStatisticsTable.hpp). Then
// <R_g^2> = A N^(2 nu) fitted over the cases (analysis/PowerLawFit.hpp): nu, its error and chi^2/dof.
//
// Results: a dictionary (nu, nuError, chi2PerDof, dof, logAmplitude, and per case its N, R_g^2, R_ee^2
// and errors), written whole or not at all.
#include "analysis/PowerLawFit.hpp"
#include "io/Dictionary.hpp"

#include <iosfwd>
#include <string>
#include <vector>

namespace dpd {

struct ChainScalingCase {
    std::string dir;
    int length = 0;
    double rg2 = 0.0, rg2Error = 0.0;
    double ree2 = 0.0, ree2Error = 0.0;
};

struct ChainScalingResult {
    std::vector<ChainScalingCase> cases;  // in increasing length
    PowerLawFitResult fit;                // of R_g^2 against N: exponent 2 nu
    double nu() const { return 0.5 * fit.exponent; }
    double nuError() const { return 0.5 * fit.exponentError; }
};

// One case: InputError naming insertChainsDict's `length`, IoError naming a missing table or a table
// without the mean of R_g^2 or R_ee^2.
ChainScalingCase readChainScalingCase(const std::string& dir, const std::string& function);

// Every case read, then fitted (std::invalid_argument for fewer than 3 distinct lengths or a mean or
// error that is not positive).
ChainScalingResult chainScaling(const std::vector<std::string>& dirs, const std::string& function);

Dictionary chainScalingDictionary(const ChainScalingResult& r);
void printChainScaling(std::ostream& out, const ChainScalingResult& r);

}  // namespace dpd
