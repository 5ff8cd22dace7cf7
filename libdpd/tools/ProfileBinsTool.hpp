#pragma once
// profileBins: turns the bin sums the solver accumulated (<time>/sampling/<name>.h5) into profile
// tables, postProcessing/profileBins/<time>/<name>.dat (see ProfileTable.hpp), and summarises each.
// With `snapshot`, it bins the instantaneous particles of <time>/particles.h5 instead, as set in
// system/profileBinsDict:
//
//   axis     z;          // x | y | z (no y in a 2-D scene)
//   nBins    40;
//   min      -5;         // optional, default: the box
//   max      5;
//   species  (fluid);    // optional, default: every species that is not frozen
//
// and writes postProcessing/profileBins/<time>/snapshot.dat (one sample, so the error columns are 0).
// Instead of axis, `axes (x z); nBins (160 80);` bins on a 2-D grid (sampling/BinLayoutDictionary.hpp),
// from the solver's 2-D sampling files as from snapshots: the table then has both axes as its first
// two columns, <name>.vti holds the same fields as VTK image data for ParaView (ProfileGrid.hpp), and
// each of `sections (...)` gives a 1-D table <name>_<axis><position>.dat along the second axis.
//
// Every profile of every selected time is computed before anything is written, so an error leaves
// the case as it was.
#include "sampling/BinAccumulatorFile.hpp"
#include "sampling/BinProfile.hpp"

#include <iosfwd>
#include <string>
#include <vector>

namespace dpd {

class Dictionary;
struct Snapshot;

// What a person checks first: is the bulk density and temperature what the case asked for.
struct ProfileSummary {
    long samples = 0;
    int blocksForErrors = 0;     // 0: no error bars
    int binsUsed = 0;            // the central bins the means are taken over
    double density = 0.0;        // mean number density over the central bins
    double densityErr = 0.0;     // standard error from the spread of block means (0 when unknown)
    double kT = 0.0;             // count-weighted mean kT over the central bins
    double kTErr = 0.0;
};

// Means over the bins whose centres lie farther than `margin` from both ends of [lo, hi] (all bins
// when none does). Bins with fewer than 3 particle-samples carry no temperature and are left out of
// the kT mean. No error bars: samples and blocksForErrors are copied from the profile, errors are 0.
ProfileSummary summariseProfile(const BinProfile& profile, double lo, double hi, double margin);
// The same from stored bins, with standard errors from the spread of the per-block means over the
// complete blocks (when there are at least two).
ProfileSummary summariseBins(const StoredBins& bins, double margin);

// The bin layout and species of system/profileBinsDict, checked against a snapshot (box, species).
// Errors are InputErrors naming the dictionary, the line and the keyword.
BinAccumulator snapshotAccumulator(const Dictionary& dict, const Snapshot& snapshot);
// One sample of the snapshot's particles binned as the dictionary says.
BinProfile binSnapshot(const Dictionary& dict, const Snapshot& snapshot, BinLayout* layoutOut = nullptr);

struct ProfileBinsOptions {
    std::string caseDir = ".";
    std::string time;         // -time
    bool latestTime = false;  // -latestTime
    bool snapshot = false;    // -snapshot
    double margin = 1.0;      // bins this close to the ends are left out of the summary (one cutoff)
};

struct ProfileBinsItem {
    std::string time;       // the time directory's name
    std::string name;       // the sampling function's name, or "snapshot"
    std::string axisName;   // x, y or z
    std::string source;     // the file read
    std::string output;     // the table to write, <case>/postProcessing/profileBins/<time>/<name>.dat
    BinLayout layout;       // a 2-D grid also writes <name>.vti and one <name>_<axis><position>.dat per section
    std::vector<double> sections;
    BinProfile profile;
    ProfileSummary summary;
};

// Reads and computes everything; writes nothing. IoError for a selected time without sampling files
// (when the time was asked for by -time or -latestTime, or when no time of the default selection
// has any; otherwise such times are skipped and listed in `skipped`).
std::vector<ProfileBinsItem> computeProfileBins(const ProfileBinsOptions& options,
                                                std::vector<std::string>* skipped = nullptr);
void writeProfileBins(const std::vector<ProfileBinsItem>& items);
void printProfileBins(std::ostream& out, const std::vector<ProfileBinsItem>& items, const std::string& caseDir);
// compute, then write, then print; notes about skipped times go to `out` too.
std::vector<ProfileBinsItem> runProfileBins(const ProfileBinsOptions& options, std::ostream& out);

}  // namespace dpd
