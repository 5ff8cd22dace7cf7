#pragma once
// slipTensor: the effective slip tensor of a channel between striped walls (docs/analysis.md 5.4), from
// one run driven at an angle theta to the stripes.
//
// Averaged along the stripes' axis, each in-plane velocity component is the Poiseuille parabola of its
// own force component (the stripes' pressure field averages out over a period), so fitSlipLength's
// Poiseuille fit (system/fitSlipLengthDict: mode poiseuille, its profile and exclude; component is set
// here) of the component along the stripes gives b_par, across them b_perp, per wall with errors. From
// them b_eff(theta) = b_par cos^2 theta + b_perp sin^2 theta (mean of the walls). The fluxes per unit
// width, Q = sum over the bins of (n / n_central) u dz, along and across the stripes, give the measured
// transverse flux ratio: the flux across the force over the flux along it, positive towards the
// stripes (analysis/StripedSlip.hpp: transverseFluxRatio). Errors come from the sampling file's blocks
// (their correlation measured, analysis/CorrelatedMean.hpp) when it is there. A component without
// force is not fitted (its slip lengths are NaN); its flux is still measured and should vanish.
//
// Results: postProcessing/slipTensor/<time>/fit.dat (a dictionary; runSweep collects it with
// -fit postProcessing/slipTensor). The channel's planar walls must be striped tunable-slip walls along
// the profile's axis, their stripes along one axis.
#include "tools/FitSlipLengthTool.hpp"

#include <iosfwd>
#include <string>
#include <vector>

namespace dpd {

// A flux per unit width with its standard error and the blocks it was measured in.
struct MeasuredFlux {
    double value = 0.0;
    double error = 0.0;
    std::vector<double> blocks;  // empty: errors with the bins taken as independent
};

struct SlipTensorResult {
    std::string time;
    std::string profileFile;
    int axis = 2;                 // the profile's axis (the walls' normal)
    int parallelAxis = 1;         // along the stripes
    int perpendicularAxis = 0;    // across them (the stripes' axis)
    double gParallel = 0.0, gPerpendicular = 0.0;
    double thetaDegrees = 0.0;    // the force's angle to the stripes
    bool parallelFitted = false, perpendicularFitted = false;
    FitSlipLengthResult parallel, perpendicular;  // the fits, where the component is driven
    MeasuredFlux fluxParallel, fluxPerpendicular;
    double transverseFluxRatio = 0.0, transverseFluxRatioError = 0.0;
    double densityCentral = 0.0;
    int binsInFlux = 0;           // bins with a velocity in every block (the others hold no fluid)

    // Mean of the two walls, and its error.
    static double wallsMean(const FitSlipLengthResult& r);
    static double wallsMeanError(const FitSlipLengthResult& r);
    double slipParallel() const;       // NaN when not fitted
    double slipPerpendicular() const;
    double slipEffective() const;      // b_eff(theta) from the fitted components
    double slipEffectiveError() const;
};

// One profile table (with its blocks, read from `samplingFile` when it exists). InputError naming
// fitSlipLengthDict or dpdProperties when the setup does not fit.
SlipTensorResult slipTensor(const Dictionary& fitDict, const Dictionary& dpdProperties, const std::string& caseDir,
                            const ProfileTableData& table,
                            const std::string& samplingFile, const std::string& time = "");

Dictionary slipTensorDictionary(const SlipTensorResult& r);
void printSlipTensor(std::ostream& out, const SlipTensorResult& r);

// The whole tool: every selected time, results written after all are computed.
std::vector<SlipTensorResult> runSlipTensor(const FitSlipLengthOptions& options, std::ostream& out);

}  // namespace dpd
