// compareFVM's 2-D comparison pieces on fields of known answer: the grid of a 2-D profile table's bin
// centres, finite-volume cells gathered into bins, sampled lines with gaps, and Darcy's superficial
// velocity and permeability k = nu u_s / g from both sides (foam/DarcyFlow.hpp).
#include "foam/DarcyFlow.hpp"
#include "foam/FieldComparison.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace {

// The bin centres of an n0 x n1 grid over [lo0, hi0) x [lo1, hi1), first axis fastest.
void gridCentres(int n0, int n1, double lo0, double hi0, double lo1, double hi1, std::vector<double>& c0,
                 std::vector<double>& c1) {
    for (int j = 0; j < n1; ++j)
        for (int i = 0; i < n0; ++i) {
            c0.push_back(lo0 + (i + 0.5) * (hi0 - lo0) / n0);
            c1.push_back(lo1 + (j + 0.5) * (hi1 - lo1) / n1);
        }
}

// Cell centres of a uniform mesh m0 x m1 over the same rectangle (y = 0), in the x-z plane, skipping
// the cells `solid` says are solid; U from the function u(x, z) along x.
template <class Solid, class Field>
void mesh(int m0, int m1, double lo0, double hi0, double lo1, double hi1, Solid solid, Field u,
          std::vector<Eigen::Vector3d>& C, std::vector<Eigen::Vector3d>& U) {
    for (int k = 0; k < m1; ++k)
        for (int i = 0; i < m0; ++i) {
            const double x = lo0 + (i + 0.5) * (hi0 - lo0) / m0, z = lo1 + (k + 0.5) * (hi1 - lo1) / m1;
            if (solid(x, z)) continue;
            C.emplace_back(x, 0.0, z);
            U.emplace_back(u(x, z), 0.0, 0.0);
        }
}

TEST(BinGrid, CentresOfATableGiveBackTheGridAndBinIndices) {
    std::vector<double> c0, c1;
    gridCentres(6, 4, -3, 3, 0, 2, c0, c1);
    const dpd::BinGrid g = dpd::gridOfCentres(0, 2, c0, c1);
    EXPECT_EQ(g.n0, 6);
    EXPECT_EQ(g.n1, 4);
    EXPECT_NEAR(g.lo0, -3, 1e-12);
    EXPECT_NEAR(g.hi0, 3, 1e-12);
    EXPECT_NEAR(g.lo1, 0, 1e-12);
    EXPECT_NEAR(g.hi1, 2, 1e-12);
    for (std::size_t k = 0; k < c0.size(); ++k) EXPECT_EQ(g.index(c0[k], c1[k]), static_cast<long>(k));
    EXPECT_EQ(g.index(3.0, 1.0), -1);   // the upper edge is outside
    EXPECT_EQ(g.index(-3.0, 0.0), 0);
    // Not a grid: a centre out of place, or the second axis fastest.
    std::vector<double> bad = c0;
    bad[7] += 0.1;
    EXPECT_THROW(dpd::gridOfCentres(0, 2, bad, c1), std::invalid_argument);
    EXPECT_THROW(dpd::gridOfCentres(0, 2, c1, c0), std::invalid_argument);
}

// A field linear in x and z, on a mesh twice as fine as the bins: each bin's mean over its four cells is
// the value at the bin centre exactly. Cells cut out (solid) leave the mean over the rest; a bin with no
// cell left has no value.
TEST(BinGrid, CellsGatheredIntoBinsAverageTheFluidCells) {
    std::vector<double> c0, c1;
    gridCentres(4, 3, 0, 4, 0, 3, c0, c1);
    const dpd::BinGrid g = dpd::gridOfCentres(0, 2, c0, c1);
    const auto u = [](double x, double z) { return 1.0 + 0.5 * x - 0.25 * z; };
    std::vector<Eigen::Vector3d> C, U;
    // Solid: the whole bin (3, 2) and the lower-left cell of bin (0, 0).
    const auto solid = [](double x, double z) { return (x > 3 && z > 2) || (x < 0.5 && z < 0.5); };
    mesh(8, 6, 0, 4, 0, 3, solid, u, C, U);
    const dpd::BinnedCells b = dpd::binCells(C, U, 0, g);
    for (std::size_t k = 1; k + 1 < g.size(); ++k) {
        EXPECT_EQ(b.cells[k], 4);
        EXPECT_NEAR(b.mean(k), u(c0[k], c1[k]), 1e-12);
    }
    EXPECT_EQ(b.cells[0], 3);
    EXPECT_NEAR(b.mean(0), (u(1.5 * 0.5, 0.25) + u(0.25, 0.75) + u(0.75, 0.75)) / 3, 1e-12);
    EXPECT_TRUE(std::isnan(b.mean(g.size() - 1)));
}

TEST(SampledLine, InterpolationStopsAtGapsInTheSamples) {
    const std::vector<double> x{0, 1, 2, 5, 6};   // no sample between 2 and 5 (solid)
    const std::vector<double> v{0, 2, 4, 10, 12};
    EXPECT_DOUBLE_EQ(dpd::interpolateAcrossSamples(x, v, 1.5, 1.5), 3.0);
    EXPECT_DOUBLE_EQ(dpd::interpolateAcrossSamples(x, v, 5.5, 1.5), 11.0);
    EXPECT_TRUE(std::isnan(dpd::interpolateAcrossSamples(x, v, 3.0, 1.5)));
    EXPECT_TRUE(std::isnan(dpd::interpolateAcrossSamples(x, v, 6.5, 1.5)));
}

// A uniform velocity filling the rectangle: u_s = u0 and k = nu u0 / g exactly, on both sides; with a
// quarter of the rectangle solid (and no flow there) the porosity is 3/4 and u_s = 3/4 u0.
TEST(DarcyFlow, UniformFlowGivesThePermeabilityExactly) {
    const double u0 = 0.3, nu = 0.27, g = 0.01;
    std::vector<double> c0, c1;
    gridCentres(4, 4, 0, 4, 0, 4, c0, c1);
    const dpd::BinGrid grid = dpd::gridOfCentres(0, 2, c0, c1);
    for (const bool withSolid : {false, true}) {
        const auto solid = [&](double x, double z) { return withSolid && x > 2 && z > 2; };
        std::vector<Eigen::Vector3d> C, U;
        mesh(8, 8, 0, 4, 0, 4, solid, [&](double, double) { return u0; }, C, U);
        const dpd::DarcyFlow fvm = dpd::darcyFromCells(dpd::binCells(C, U, 0, grid), 4.0, nu, g);
        std::vector<double> density, u, err;
        for (std::size_t k = 0; k < c0.size(); ++k) {
            const bool s = solid(c0[k], c1[k]);
            density.push_back(s ? 0.0 : 4.0);
            u.push_back(s ? 0.0 : u0);
            err.push_back(s ? 0.0 : 0.02);
        }
        const dpd::DarcyFlow dpdSide = dpd::darcyFromBins(density, u, err, 4.0, nu, g);
        const double phi = withSolid ? 0.75 : 1.0;
        for (const dpd::DarcyFlow& d : {fvm, dpdSide}) {
            EXPECT_NEAR(d.porosity, phi, 1e-14);
            EXPECT_NEAR(d.superficialVelocity, phi * u0, 1e-14);
            EXPECT_NEAR(d.permeability, nu * phi * u0 / g, 1e-12);
        }
        // Independent bins of error e: the mean over N bins of which n are fluid has error sqrt(n) e / N.
        const double n = phi * 16;
        EXPECT_NEAR(dpdSide.superficialVelocityErr, std::sqrt(n) * 0.02 / 16, 1e-14);
        EXPECT_NEAR(dpdSide.permeabilityErr, nu * dpdSide.superficialVelocityErr / g, 1e-14);
    }
}

// Plane Poiseuille flow in a slit of width d inside a period H (the rest solid): u_s = g d^3 / (12 nu H),
// so k = d^3 / (12 H). The cells sample the parabola at their centres, a midpoint rule whose error is
// known exactly for a parabola: sum h u(z_i) = integral + g h^2 d / (24 nu), so on the mesh
// k = (d^3 / 12 + h^2 d / 24) / H.
TEST(DarcyFlow, SlitFlowGivesTheSlitPermeability) {
    const double nu = 0.27, g = 0.01, d = 6.0, H = 10.0, h = 0.5;
    std::vector<double> c0, c1;
    gridCentres(4, 10, 0, 4, 0, H, c0, c1);
    const dpd::BinGrid grid = dpd::gridOfCentres(0, 2, c0, c1);
    std::vector<Eigen::Vector3d> C, U;
    mesh(8, 20, 0, 4, 0, H, [&](double, double z) { return z > d; },
         [&](double, double z) { return g / (2 * nu) * z * (d - z); }, C, U);
    const dpd::DarcyFlow f = dpd::darcyFromCells(dpd::binCells(C, U, 0, grid), 4.0, nu, g);
    EXPECT_NEAR(f.porosity, d / H, 1e-14);
    EXPECT_NEAR(f.permeability, (d * d * d / 12 + h * h * d / 24) / H, 1e-12);
}

TEST(DarcyFlow, BadInputIsRefused) {
    EXPECT_THROW(dpd::darcyFromBins({4, 4}, {1}, {}, 4, 0.3, 0.01), std::invalid_argument);
    EXPECT_THROW(dpd::darcyFromBins({4}, {1}, {}, 0, 0.3, 0.01), std::invalid_argument);
    EXPECT_THROW(dpd::darcyFromBins({4}, {1}, {}, 4, 0.3, 0.0), std::invalid_argument);
    dpd::BinnedCells b;
    b.sum = {1.0};
    b.cells = {1};
    EXPECT_THROW(dpd::darcyFromCells(b, 0.0, 0.3, 0.01), std::invalid_argument);
    EXPECT_THROW(dpd::darcyFromCells(b, 1.0, -0.3, 0.01), std::invalid_argument);
}

}  // namespace
