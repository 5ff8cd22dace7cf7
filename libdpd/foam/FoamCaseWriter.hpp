#pragma once
// Writes the OpenFOAM case of a FoamCaseSpec, a normal simpleFoam case that a user opens, edits and
// reruns:
//
//   0/U, 0/p                      no-slip walls (fixedValue for moving ones, partialSlip for Navier slip),
//                                 cyclic periodic pairs, empty front and back in 2-D; p periodic, no
//                                 mean pressure gradient (the body force drives the flow)
//   constant/transportProperties  Newtonian, nu = the DPD fluid's measured viscosity
//   constant/turbulenceProperties laminar
//   constant/dpdCase              where the case came from: DPD box, walls, g, nu (read by compareFVM)
//   system/blockMeshDict          one block over the mesh's extent
//   system/fvOptions              the body force: vectorSemiImplicitSource on all cells
//   system/controlDict            simpleFoam; a `sets` function object sampling the lines (raw)
//   system/fvSchemes, fvSolution  SIMPLEC, converged to `residual` in a few hundred iterations
//   system/topoSetDict            only with solid cells: the fluid cellSet for subsetMesh
//   constant/staircaseSlip,       only with a slipping geometry wall: each staircase face's valueFraction
//   staircaseSlip.awk               by its centre, given to solidWalls by the Allrun after subsetMesh
//   Allrun, Allclean              blockMesh [topoSet, subsetMesh], simpleFoam, writeCellCentres
//
// Navier slip u_w = beta du/dn on a partialSlip wall: the wall value is (1 - f) times the tangential
// velocity of the wall cell, and the wall gradient is taken over the half cell h/2, so
// u_w = beta (U_P - u_w) / (h/2) gives f = (h/2) / (beta + h/2).
#include "foam/FoamCaseSpec.hpp"

#include <string>

namespace dpd {

// The text of each file (for tests).
std::string foamBlockMeshDict(const FoamCaseSpec& s);
std::string foamVelocityField(const FoamCaseSpec& s);
std::string foamPressureField(const FoamCaseSpec& s);
std::string foamControlDict(const FoamCaseSpec& s);
std::string foamFvOptions(const FoamCaseSpec& s);
std::string foamTopoSetDict(const FoamCaseSpec& s);
std::string foamCaseRecord(const FoamCaseSpec& s);
std::string foamStaircaseSlip(const FoamCaseSpec& s);
// The partialSlip value fraction of a wall with slip length beta and wall-normal cell size h.
double partialSlipValueFraction(double beta, double h);

// Writes every file under dir (created if needed); each file atomically. IoError when it cannot.
void writeFoamCase(const FoamCaseSpec& s, const std::string& dir);

}  // namespace dpd
