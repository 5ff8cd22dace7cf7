#pragma once
// The continuum reference for the effective slip of striped (superhydrophobic) walls (docs/analysis.md
// 5.1; the walls themselves: docs/walls.md 3.6). The wall y = 0 carries stripes of period L along x,
// running along z: gas sectors, a fraction phi2 of each period, with a local Navier slip length b
// (u_t = b du_t/dn; b infinite: shear-free), and no slip on the rest. The effective slip is a tensor:
// b_par for flow along the stripes, b_perp across them.
//   - A single wall (H infinite) under a far-field shear S: u -> S (y + b_eff) far from it.
//   - A channel of height H driven by a pressure gradient, with one striped wall facing a no-slip wall
//     or two striped walls in phase: b_eff is the Navier slip length of the same walls made uniform that
//     passes the same flux, Q / Q_no-slip = (H + 4 b_eff) / (H + b_eff) or 1 + 6 b_eff / H.
// Lengths are in the caller's units (the results scale with L). Throws std::invalid_argument on
// L <= 0, phi2 outside [0, 1], b < 0, H <= 0, stripedWalls not 1 or 2, or two striped walls with H infinite.
#include <limits>

namespace dpd {

struct StripedWall {
    double period = 1.0;                                           // L
    double slipFraction = 0.5;                                     // phi2 = 1 - phi1
    double localSlip = std::numeric_limits<double>::infinity();    // b; infinite: shear-free gas sectors
    double height = std::numeric_limits<double>::infinity();       // H; infinite: a single wall in shear
    int stripedWalls = 1;                                          // 1, or 2 in phase (channel only)
};

// Sizes of the numerical solution; 0 asks for the automatic choice (stripedSlipResolution; modes 0 with
// a basis given: the modes that basis needs).
struct StripedSlipResolution {
    int basis = 0;  // sector functions per gas sector
    int modes = 0;  // Fourier modes summed exactly (the tail beyond is added from its asymptote)
};

struct SlipTensor {
    double parallel = 0.0;       // b_par, along the stripes
    double perpendicular = 0.0;  // b_perp, across them
};

// The automatic resolution: relative error below 1e-4 against Philip's exact result and under doubling
// (docs/analysis.md 5.1, "Resolution and accuracy").
StripedSlipResolution stripedSlipResolution(const StripedWall& wall);

// The numerical solution (Laplace for b_par, biharmonic stream function for b_perp). phi2 = 0 or b = 0
// give 0 and phi2 = 1 gives b exactly (the wall is uniform).
double longitudinalSlip(const StripedWall& wall, StripedSlipResolution resolution = {});
double transverseSlip(const StripedWall& wall, StripedSlipResolution resolution = {});
SlipTensor stripedSlipTensor(const StripedWall& wall, StripedSlipResolution resolution = {});

// The slip along a direction at angle theta to the stripes: b_par cos^2 theta + b_perp sin^2 theta.
double effectiveSlip(const SlipTensor& slip, double theta);

// Philip (1972), perfect-slip stripes under shear: b_par = 2 b_perp = (L / pi) ln sec(pi phi2 / 2).
double philipLongitudinalSlip(double period, double slipFraction);
double philipTransverseSlip(double period, double slipFraction);

// Belyaev and Vinogradova (2010), any local slip b (infinite allowed), single wall:
//   b_par  / L = (1 / pi)     ln sec(pi phi2/2) / (1 + L / (pi b)   ln[sec(pi phi2/2) + tan(pi phi2/2)]),
//   b_perp / L = (1 / (2 pi)) ln sec(pi phi2/2) / (1 + L / (2 pi b) ln[sec(pi phi2/2) + tan(pi phi2/2)]).
double belyaevVinogradovaLongitudinalSlip(double period, double slipFraction, double localSlip);
double belyaevVinogradovaTransverseSlip(double period, double slipFraction, double localSlip);

// The thin-channel limits (H << L, lubrication over each stripe) of the channel's b_par and b_perp
// (finite H only): with c = 1, 4 (one striped wall) or 6 (two),
//   b_par  = phi2 b H / (H + phi1 b)       (one striped wall),   phi2 b   (two),
//   b_perp = phi2 b H / (H + c phi1 b),
// the mean of the local flux factor and of its inverse over the period (docs/analysis.md 5.1).
double thinChannelLongitudinalSlip(const StripedWall& wall);
double thinChannelTransverseSlip(const StripedWall& wall);

// Q / Q_no-slip of a channel of height H whose striped wall(s) had the uniform slip length `slip`:
// (H + 4 slip) / (H + slip) for one, 1 + 6 slip / H for two.
double channelFluxFactor(double slip, double height, int stripedWalls);

// A channel driven at angle theta to the stripes: the flux across the driving force (towards the
// stripes) over the flux along it, from the flux tensor Q_par e_par e_par + Q_perp e_perp e_perp:
//   (Q_par - Q_perp) sin theta cos theta / (Q_par cos^2 theta + Q_perp sin^2 theta).
double transverseFluxRatio(const SlipTensor& slip, double height, int stripedWalls, double theta);
double transverseFluxRatio(const StripedWall& wall, double theta, StripedSlipResolution resolution = {});

}  // namespace dpd
