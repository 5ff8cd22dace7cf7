#pragma once
// fitSlipLength: viscosity and wall slip from a profile table written by profileBins, as set in
// system/fitSlipLengthDict:
//
//   mode       poiseuille;      // poiseuille | reversePoiseuille | couette
//   profile    channelProfile;  // the table postProcessing/profileBins/<time>/<profile>.dat
//   component  x;               // the velocity component along the flow; default: the direction of
//                               // the body force (when it has exactly one nonzero component)
//   exclude    0;               // poiseuille: distance from each wall left out of the fit (default 0);
//                               // reversePoiseuille: half-width of the band left out around the
//                               // planes where the force jumps (default 1);
//                               // couette: distance from each wall left out (default 1 cutoff)
//   fitRange   (-10 10);        // couette only, instead of exclude: the range of the profile axis
//                               // the line is fitted over
//   slipPredictionNu 0.3;       // optional: the kinematic viscosity for the predicted slip length of
//                               // tunable-slip walls (default: the fit's own nu)
//   superBlocks { decayTimes 2; }  // optional: errors by jackknife over super-blocks (FitSuperBlocks.hpp)
//   wallPositions (-20 20);     // poiseuille, couette: the channel's walls along the profile's axis
//                               // when they are not planar walls of dpdProperties but the solid of a
//                               // geometry block (randomEquilWall); such walls are at rest. An error
//                               // when the case has planar walls along that axis (theirs are used)
//
// When a channel wall has tunable slip (walls/TunableSlipLayer.hpp) the predicted slip length is written
// beside the measured one (analysis/TunableSlipPrediction.hpp): slipLengthPredicted (lower upper).
//
// poiseuille: the walls are the two planar walls of constant/dpdProperties whose normals lie along
// the profile's axis; g is the uniform body force's component along `component`, and the walls'
// velocities along it give the slip velocities (PoiseuilleFit.hpp: fitPoiseuille).
// reversePoiseuille: g from the reversePoiseuille body force; the box along the gradient axis is
// taken from the profile's bins (first centre - half a bin to last centre + half a bin), so the bins
// must cover the whole box (fitReversePoiseuille).
//
// couette: no body force; the same two walls, sliding (the component defaults to the one axis along
// which the walls move); a line is fitted over the central part (CouetteFit.hpp: fitCouette). When
// the table has the shear stress column sigma<component><axis> (binnedProfile with stress yes), the
// viscosity is <sigma> / shear rate over the fitted range, and nu = eta / rho with rho the central
// density.
//
// Bins with fewer than 3 particle-samples (no velocity) are left out. When the error column is all
// zero (a snapshot profile) the fit uses unit weights and scales the covariance by chi2/dof; when only
// some errors are zero, those bins are left out (too few blocks saw particles there) and counted.
//
// Errors: the bins of a flow profile fluctuate together (the flow rate wanders with the channel's
// slowest mode), so when the table's sampling file <time>/sampling/<profile>.h5 is there, with the same
// bins and at least 4 complete blocks in which every fitted bin saw particles, the errors of the fitted
// quantities come from the covariance of the bins over the blocks (analysis/Profile1D.hpp; fit.dat:
// errors blockCovariance, errorBlocks m). Otherwise (a snapshot profile, a section of a 2-D grid) the
// bins are taken as independent (errors independentBins) and the printed result says why. Blocks must
// be long against the slowest flow mode for either to hold.
//
// With superBlocks (mode poiseuille), the errors of nu, the slip lengths and velocities are the
// jackknife's over super-blocks long against that mode (fit.dat: errors jackknife, superBlocks m,
// blocksPerSuperBlock, superBlockLength); with too few super-blocks they stay the blocks' and
// superBlocksNote says why.
//
// Results: postProcessing/fitSlipLength/<time>/fit.dat, a dictionary. Every selected time is fitted
// before anything is written, so an error leaves the case as it was.
#include "analysis/CouetteFit.hpp"
#include "analysis/PoiseuilleFit.hpp"
#include "analysis/TunableSlipPrediction.hpp"
#include "io/Dictionary.hpp"
#include "io/TimeDirectories.hpp"
#include "case/DpdProperties.hpp"
#include "sampling/ProfileTable.hpp"
#include "tools/FitSuperBlocks.hpp"

#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

namespace dpd {

class FitMode;

// The dictionary with the model it refers to; read once, used for every time.
struct FitSlipLengthSetup {
    Dictionary dict;                  // system/fitSlipLengthDict (errors point into it)
    Dictionary dpdProperties;         // constant/dpdProperties (errors about walls and body force)
    DpdModel model;
    std::shared_ptr<const FitMode> mode;  // tools/FitMode.hpp: one of fitModes()
    std::string profile;              // table name without .dat
    int component = -1;               // -1 until resolved from the body force
    double exclude = 0.0;
    bool hasFitRange = false;         // couette: fitRange given
    double fitLow = 0.0, fitHigh = 0.0;
    double slipPredictionNu = 0.0;    // > 0: slipPredictionNu given
    bool hasWallPositions = false;    // wallPositions given: walls of a geometry, at rest
    double wallLow = 0.0, wallHigh = 0.0;
    bool predictTunableSlip = true;   // false: no predicted slip length (a striped wall's is not the formula's)
    SuperBlockSetup superBlocks;      // errors by jackknife over super-blocks, when on
};

// Checks keywords (unknown ones, mode, component, exclude) and resolves the component and the body
// force; InputError naming the file, line and keyword.
FitSlipLengthSetup readFitSlipLengthSetup(const Dictionary& dict, const Dictionary& dpdProperties, const std::string& caseDir);

struct FitSlipLengthResult {
    std::shared_ptr<const FitMode> mode;
    std::string time;
    std::string profileFile;
    int axis = 2;             // the profile's axis
    int component = 0;        // the fitted velocity component
    double g = 0.0;           // body force along the component
    double exclude = 0.0;
    int pointsUsed = 0;       // bins handed to the fit (before its own range selection)
    int binsWithoutVelocity = 0;  // fewer than 3 particle-samples: left out
    int binsWithoutError = 0;     // zero error among positive ones: left out
    BlockErrorInfo blockErrors;   // blocks > 0: errors from the fit applied block by block
    std::string errorNote;        // why the bins were taken as independent
    PoiseuilleFitResult poiseuille;     // mode poiseuille
    ReversePoiseuilleResult reverse;    // mode reversePoiseuille
    CouetteFitResult couette;           // mode couette
    bool hasStress = false;             // couette: the table had the shear stress column
    std::string stressColumn;
    StressViscosity stress;
    double boxLow = 0.0, boxLength = 0.0;  // reversePoiseuille: the periodic box along the axis
    // Kinetic-theory estimate for reference (NaN when there is no pair of mobile species).
    double densityCentral = 0.0;  // count-weighted mean density of the central half of the bins
    double gamma = 0.0;
    double nuKineticTheory = 0.0;
    TunableSlipPrediction slipPrediction;  // channel modes with tunable-slip walls
    SuperBlockInfo superBlocks;            // the jackknife, when the setup asks for it
};

// The table's bins block by block (velocities[k][row], NaN where block k saw no particles in the row),
// and why there are none when there are none.
struct TableBlocks {
    std::vector<std::vector<double>> velocities;
    std::vector<std::vector<double>> shearStress;  // the same blocks' shear stress per row, when sampled
    BlockSums sums;           // the same blocks' particle-samples and velocity sums per row
    long blockSamples = 0;    // samples in a complete block
    std::string note;
};

// The blocks of the sampling file a table was made from, when its bins are the table's (IoError for an
// unreadable file).
TableBlocks readTableBlocks(const std::string& samplingFile, const ProfileTableData& table, int component);

// Fits one profile table (with its blocks, when known). InputError (naming fitSlipLengthDict or dpdProperties) when the setup does
// not fit the table or the fit cannot be made (too few points), IoError for a missing column.
FitSlipLengthResult fitSlipLength(const FitSlipLengthSetup& setup, const ProfileTableData& table,
                                  const std::string& time = "", const TableBlocks& blocks = {});

// The result as the dictionary written to fit.dat.
Dictionary fitSlipLengthDictionary(const FitSlipLengthResult& r);
void printFitSlipLength(std::ostream& out, const FitSlipLengthResult& r);

struct FitSlipLengthOptions {
    std::string caseDir = ".";
    std::string time;
    bool latestTime = false;
};

// Where profileBins wrote a case's table, and the times that hold it as the options select them
// (InputError naming the dictionary's `profile` when a named time lacks it or no time has it).
std::string profileTablePath(const std::string& caseDir, const std::string& time, const std::string& profile);
TimesWithInput selectProfileTimes(const FitSlipLengthOptions& options, const Dictionary& dict, const std::string& profile);

// The whole tool: reads the dictionary and constant/dpdProperties, fits every selected time, then
// writes <case>/postProcessing/fitSlipLength/<time>/fit.dat and prints each result. In the default
// selection (every time but 0) times without the profile table are skipped, as long as one has it;
// a time named by -time or -latestTime must have it.
std::vector<FitSlipLengthResult> runFitSlipLength(const FitSlipLengthOptions& options, std::ostream& out);

}  // namespace dpd
