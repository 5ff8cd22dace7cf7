#pragma once
// How the flow above a striped wall answers one Fourier mode of the wall's slip velocity
// (docs/analysis.md 5.1, "The mean flow and one mode"). A slip velocity s cos(kx) on the wall y = 0, with
// the far side (no slip at y = H, or the mirror plane y = H/2 of two striped walls, or nothing for H
// infinite) as it is, gives the wall shear -g(k) s cos(kx); g is the wall's Dirichlet-to-Neumann symbol:
//   longitudinal (Laplace, w = f(y) cos kx):  k, k coth(kH), k tanh(kH/2);
//   transverse (biharmonic stream function, psi = f(y) cos kx with psi = 0 on the wall):
//     2k,  2k (sinh h cosh h - h) / (sinh^2 h - h^2),  2k (cosh h - 1) / (sinh h - h),   h = kH,
// for a single wall, one striped wall facing a no-slip wall, and two striped walls in phase.

namespace dpd {

enum class StripedFlow { longitudinal, transverse };

// g(k) for wavenumber k > 0; height infinite for a single wall; stripedWalls 1 or 2 (2 only with a
// finite height).
double stripedModeResponse(StripedFlow flow, double k, double height, int stripedWalls);

// g(k) / k for k -> infinity: 1 for the Laplace modes, 2 for the biharmonic ones.
double stripedModeResponseSlope(StripedFlow flow);

}  // namespace dpd
