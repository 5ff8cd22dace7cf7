#pragma once
// Where a wall acts and how much it slips, from Couette and Poiseuille flow together (docs/analysis.md
// section 5.3). The Navier condition holds at a hydrodynamic wall a distance h from the channel's
// mid-plane, which need not be the geometric plane at H/2. A fit against the geometric plane gives an
// apparent slip length; the two flows see the same wall differently:
//   Couette:     the line reaches the wall's speed at A = H/2 + beta_couette = h + b;
//   Poiseuille:  the parabola's zero lies at z0 with B = z0^2 = (H/2)^2 + H beta_poiseuille = h^2 + 2 b h.
// One pair of runs leaves b's sign open (h = A -+ sqrt(A^2 - B)); a sweep of wall settings that change
// b but not where the wall acts does not: B = 2 h A - h^2 for every setting, so h is fitted to all of
// them, and each setting's slip length is b = A - h.
#include <vector>

namespace dpd {

// One wall setting: the apparent slip lengths (mean of the two walls) of a Couette and a Poiseuille run
// measured from the geometric walls, in a channel of geometric width H.
struct ApparentSlip {
    double couette = 0.0, couetteErr = 0.0;
    double poiseuille = 0.0, poiseuilleErr = 0.0;
};

struct HydrodynamicWallFit {
    double halfWidth = 0.0, halfWidthErr = 0.0;  // h, from the mid-plane
    double offset = 0.0;                         // H/2 - h: how far inside the geometric plane the wall acts
    double chi2PerDof = 0.0;                     // of B = 2 h A - h^2 over the settings
    int dof = 0;
    std::vector<double> slipLength, slipLengthErr;  // b = A - h per setting; the errors share h's
};

// Fits h to B_i = 2 h A_i - h^2 (errors of A and B combined at each h, minimised over h) and gives
// b_i = A_i - h. Throws std::invalid_argument for a width <= 0, fewer than two settings, an error <= 0
// or not finite, or settings whose Couette slip lengths do not differ by more than their errors (no
// leverage on h).
HydrodynamicWallFit fitHydrodynamicWall(double width, const std::vector<ApparentSlip>& settings);

}  // namespace dpd
