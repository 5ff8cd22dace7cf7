#pragma once
// constant/dpdProperties: the physics of a case.
//
//   dimension      3;             // 2: the scene lives in the x-z plane
//   kT             1;
//   cutoff         1;
//   seed           12345;
//   weightExponent 2;             // s in w_D = (1 - r/rc)^s; 2 is standard
//   species   { fluid { frozen no; } wall { frozen yes; } }
//   pairCoeffs { fluid-fluid { a 18.75; gamma 4.5; } fluid-wall { a 18.75; gamma 4.5; } }
//              // an unlike pair left out (or given without a) is mixed: a_ij = sqrt(a_ii a_jj)
//              // (and, if left out, gamma_ij = sqrt(gamma_ii gamma_jj)); e.g. wall-wall { a 5; gamma 4.5; }
//   integrator { type GrootWarren; lambda 0.65; }   // Euler | GrootWarren (lambda) | DPDVV | Shardlow
//   bodyForce  { type uniform; value (0.02 0 0); }     // none | uniform | reversePoiseuille (+ gradientAxis z)
//   walls      { lower { type plane; point (0 0 -20); normal (0 0 1); velocity (0 0 0); reflection bounceBack; }
//                grains { type geometry; reflection bounceLayer; alpha 0.1; } }
//              // type: plane | geometry (the solid of the geometry block); walls/WallTypes.cpp
//              // reflection: none | specular | bounceBack | maxwellian | bounceForward (reverseFrame
//              //             wall | lab) | bounceLayer (with alpha 0.1: the layer is alpha x cutoff
//              //             thick); walls/WallRuleTypes.cpp. Any rule on any shape.
//              // frozen particles behind a planar wall move with its velocity
//              // tunableSlip { gammaL 2; zc 1; epsilon 1; sigma 0.5; }: a plane's or a geometry's friction
//              // layer acting on the fluid within zc (friction gammaL) with a WCA repulsion
//              // (walls/TunableSlipLayer.hpp); its reflection defaults to specular, a safety net behind it
//              // slipLength 1; with tunableSlip { zc 1; epsilon 1; sigma 0.5; } (no gammaL): the wall
//              // gives slip length 1 measured from its point (a geometry's: its surface), gammaL and how
//              // far behind it acts from the case's slip calibration (case/CaseSlipCalibrations.hpp,
//              // docs/walls.md 3.8-3.9)
//   stability  { maxKTRatio 2; maxInsideWalls 0; checkInterval 100; }   // optional; checkInterval in
//                                                 // steps, besides every report and every write
//   bonds      { type FENE; H 6; rMax 3; bondedPairs { dpd all; } }   // optional: polymer chains (their
//                                                 // bonds are in the snapshot); bondedPairs dpd all | none
//                                                 // | weighted (with weight w), forces/BondedPairs.hpp
//   geometry   { type imageMask; file "constant/geometry/mask.png"; ... }   // optional: a solid of any
//                                                 // shape (geometry/GeometryDictionary.hpp)
//                                                 // A geometry block without a geometry wall gets one,
//                                                 // named geometry, reflection bounceBack. The older
//                                                 // geometryWall { reflection ...; alpha ...; } still
//                                                 // reads as that wall, with a note in the log.
//
// Every pair of species that can interact (at least one not frozen) needs its coefficients; pairs
// of frozen species never interact and need none.
#include "core/Species.hpp"
#include "forces/BodyForce.hpp"
#include "forces/BondPotential.hpp"
#include "forces/BondedPairs.hpp"
#include "integrators/Integrator.hpp"
#include "walls/WallList.hpp"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace dpd {

class Dictionary;
class Communicator;
class System;
struct Snapshot;

struct StabilitySettings {
    double maxKTRatio = 2.0;  // stop when the measured kT exceeds this multiple of the set kT
    long maxInsideWalls = 0;  // stop when more mobile particles than this are found inside walls
    long checkIntervalSteps = 100;  // the run's health is checked this often, and before every write
};

struct DpdModel {
    // The planar walls' settings, in the walls block's order.
    std::vector<const PlanarWallSettings*> planes() const;

    int dimension = 3;
    double kT = 1.0;
    double cutoff = 1.0;
    double weightExponent = 2.0;
    std::uint64_t seed = 1;
    SpeciesTable species;
    PairTable pairs;
    IntegratorSettings integrator;
    std::shared_ptr<const BodyForce> bodyForce = noBodyForce();
    std::shared_ptr<const BondPotential> bondPotential;  // null: the case has no bonds block
    BondedPairs bondedPairs;
    WallList walls;  // the walls block's walls; a geometry wall's shape is built on the snapshot's box
    // The planar walls' settings as read: the builders and post-processing fit channels between them.
    std::vector<PlanarWallSettings> planarWalls;
    std::string caseDir = ".";  // a geometry's files are relative to it
    StabilitySettings stability;
    std::vector<std::string> pairNotes;  // pairs whose coefficients were mixed, for the log
    std::vector<std::string> inputNotes;  // older keywords read as their newer form, for the log
    std::vector<std::string> wallNotes;   // what walls that ask for a slip length were given, for the log
};

// Reads and checks the dictionary; every error is an InputError naming file, line and keyword.
// Without the case directory, a wall that asks for a slip length is refused: its friction and plane
// come from the case's slip calibration (case/CaseSlipCalibrations.hpp).
DpdModel readDpdModel(const Dictionary& dict);
DpdModel readDpdModel(const Dictionary& dict, const std::string& caseDir);
DpdModel readDpdProperties(const std::string& caseDir);

// A ready-to-run system: the model's physics, the snapshot's particles (species matched by name),
// the time step dt. Throws InputError/IoError when the snapshot does not fit the model.
// With `ranks` (several), the system is this rank's slab of the box (System::ranks), cut as
// slabPlanes says (planes per rank; empty: balanced).
System buildSystem(const DpdModel& model, Snapshot snapshot, double dt, const std::string& snapshotFile,
                   const Communicator* ranks = nullptr, const std::vector<int>& slabPlanes = {});

}  // namespace dpd
