#pragma once
// The tunable-slip wall of Smiatek, Allen and Schmid (Eur. Phys. J. E 26, 115 (2008); docs/walls.md 3.5):
// a smooth plane that acts on each fluid particle at distance z in front of it with
//   - a dissipative force  F^D = -gamma_L w_L(z) (v - v_wall),
//   - a random force       F^R = sqrt(2 kT gamma_L w_L(z)) xi / sqrt(dt),   w_L(z) = 1 - z/z_c (z < z_c),
//     xi a vector of independent unit-variance Gaussians (one per active axis), so that the pair
//     F^D, F^R obeys fluctuation-dissipation with the wall as a heat bath at kT;
//   - a purely repulsive WCA force from V(z) = 4 eps [(s/z)^12 - (s/z)^6 + 1/4] for z < 2^(1/6) s,
//     which keeps the fluid off the plane (it diverges there).
// gamma_L sets the wall friction and with it the slip length; the predicted slip length is
//   b / z_c = 2/alpha - 7/15 - 19 alpha / 1800 + ...,   alpha = z_c^2 gamma_L rho / eta.
#include <Eigen/Core>

#include <cstddef>
#include <cstdint>

namespace dpd {

struct TunableSlipParameters {
    double gammaL = 0.0;   // wall friction coefficient
    double zc = 1.0;       // range of the friction layer in front of the plane
    double epsilon = 1.0;  // WCA energy
    double sigma = 0.5;    // WCA length: the repulsion acts for z < 2^(1/6) sigma
    // Friction and random force on the velocity along the plane only (friction tangential): the
    // published wall acts on every component, which also damps flow towards and away from the plane.
    bool tangentialOnly = false;
    // The fluid behind the plane (fluidBehind { a; density; }, not in the paper; docs/walls.md 3.5): the
    // mean conservative force of a DPD fluid of that repulsion and density filling the half-space beyond
    // the WCA's contact distance sigma, so the fluid in front is not pressed against the wall by the
    // neighbours it lacks there. Off (density 0) by default: the published wall.
    double behindA = 0.0;
    double behindDensity = 0.0;
    double cutoff = 1.0;  // the pair force's cutoff, which the fluid behind reaches across

    double wcaRange() const;
    // How far in front of the plane the wall acts at all: friction, WCA and the fluid behind.
    double reach() const;
    // w_L(z) = 1 - z/z_c for 0 <= z < z_c, else 0.
    double frictionWeight(double z) const;
    // -dV/dz for 0 < z < 2^(1/6) sigma, else 0 (positive: pushes into the fluid).
    double wcaForce(double z) const;
    // pi a rho r_c^3 (1 - x)^3 (1 + 3x) / 12, x = max(z - sigma, 0) / r_c < 1, else 0: the normal
    // component of a (1 - r/r_c) summed over the half-space (positive: pushes into the fluid).
    double fluidBehindForce(double z) const;
    // The force on a particle at distance z (> 0) in front of a wall with unit normal n into the fluid,
    // moving at vRelative to the wall; xi are its unit-variance random numbers for this step.
    Eigen::Vector3d force(double z, const Eigen::Vector3d& n, const Eigen::Vector3d& vRelative, const Eigen::Vector3d& xi,
                          double kT, double dt) const;
};

// Stripes of a tunable-slip wall (docs/walls.md 3.6): along `axis` (in the wall's plane, across the
// stripes) each period holds a gas sector of width gasFraction x period, starting at `offset`, whose
// friction is gammaGas; the rest keeps the wall's gammaL.
struct TunableSlipStripes {
    int axis = 0;
    double period = 1.0;
    double gasFraction = 0.5;
    double gammaGas = 0.0;
    double offset = 0.0;
    // Whether a coordinate along the axis lies in a gas sector.
    bool isGas(double coordinate) const;
};

// The random-number stream of tunable-slip wall k (RandomStream kStreamTunableSlip in its low byte,
// the wall's index above it): two walls that both reach a particle draw independent numbers.
std::uint32_t tunableSlipStream(std::size_t wallIndex);

// Predicted slip length b = z_c (2/alpha - 7/15 - 19 alpha/1800), alpha = z_c^2 gamma_L rho / eta, measured
// from the plane; eta = rho nu is the fluid's dynamic viscosity. Throws std::invalid_argument unless
// gamma_L, z_c, rho and eta are positive.
double tunableSlipAlpha(double gammaL, double zc, double rho, double eta);
double predictedTunableSlipLength(double gammaL, double zc, double rho, double eta);

}  // namespace dpd
