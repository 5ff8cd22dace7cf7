#include "setup/FrozenLattice.hpp"

#include <cmath>
#include <stdexcept>

namespace dpd {

namespace {

struct WallFrame {
    int normal;                  // axis of the normal
    double sign;                 // +1 if the normal points along +axis (solid below the plane)
    std::vector<int> inPlane;    // active in-plane axes
};

WallFrame frameOf(const Box& box, const PlanarWallSettings& wall) {
    WallFrame f;
    f.normal = wall.normalAxis();
    if (f.normal < 0) throw std::invalid_argument("wall '" + wall.name + "': lattice walls need an axis-aligned normal");
    f.sign = wall.normal[f.normal] > 0 ? 1.0 : -1.0;
    for (int a = 0; a < 3; ++a)
        if (a != f.normal && box.isActiveAxis(a)) f.inPlane.push_back(a);
    return f;
}

// Number of lattice cells along an in-plane axis for a wanted spacing, and the spacing that fits.
double fittedSpacing(double length, double wanted) {
    const double n = std::max(1.0, std::round(length / wanted));
    return length / n;
}

// Adds points for a layer at `depth` behind the plane, with a 2-D (or 1-D in 2-D scenes) rectangular
// grid in the plane, optionally offset by half a cell (for the staggered planes of FCC).
void addLayer(std::vector<Eigen::Vector3d>& out, const Box& box, const PlanarWallSettings& wall, const WallFrame& f,
              double depth, const std::vector<double>& spacing, const std::vector<double>& offset) {
    Eigen::Vector3d base = Eigen::Vector3d::Zero();
    base[f.normal] = wall.point[f.normal] - f.sign * depth;
    if (!box.isActiveAxis(1)) base.y() = 0.5 * (box.lo.y() + box.hi.y());
    const int a0 = f.inPlane[0];
    const int n0 = static_cast<int>(std::lround(box.length()[a0] / spacing[0]));
    const int a1 = f.inPlane.size() > 1 ? f.inPlane[1] : -1;
    const int n1 = a1 >= 0 ? static_cast<int>(std::lround(box.length()[a1] / spacing[1])) : 1;
    for (int i = 0; i < n0; ++i)
        for (int j = 0; j < n1; ++j) {
            Eigen::Vector3d r = base;
            r[a0] = box.lo[a0] + (i + 0.25 + offset[0]) * spacing[0];
            if (a1 >= 0) r[a1] = box.lo[a1] + (j + 0.25 + offset[1]) * spacing[1];
            for (int a = 0; a < 3; ++a)
                if (box.isActiveAxis(a)) r[a] = box.wrap(r[a], a);
            out.push_back(r);
        }
}

std::vector<Eigen::Vector3d> cubicOrFcc(const Box& box, const PlanarWallSettings& wall, const WallFrame& f,
                                        const FrozenLatticeSettings& s) {
    const bool fcc = s.lattice == "fcc";
    const int d = box.dimension;
    // Lattice constant from the density: fcc has 4 points per cubic cell (2 per square cell of the
    // centred-rectangular 2-D analogue), simple cubic 1.
    const double pointsPerCell = fcc ? (d == 3 ? 4.0 : 2.0) : 1.0;
    const double a = std::pow(pointsPerCell / s.density, 1.0 / d);
    std::vector<double> spacing;
    for (int axis : f.inPlane) spacing.push_back(fittedSpacing(box.length()[axis], a));
    std::vector<Eigen::Vector3d> out;
    // Planes every a/2 (fcc) or a (simple cubic) along the normal; fcc alternates the in-plane offset.
    const double planeStep = fcc ? 0.5 * a : a;
    int plane = 0;
    for (double depth = 0.5 * planeStep; depth < s.thickness; depth += planeStep, ++plane) {
        if (!fcc) { addLayer(out, box, wall, f, depth, spacing, {0.0, 0.0}); continue; }
        if (d == 3) {
            // Each fcc (100) plane holds two points per cell: (0,0) and (1/2,1/2), alternating with
            // (1/2,0) and (0,1/2) on the next plane.
            if (plane % 2 == 0) {
                addLayer(out, box, wall, f, depth, spacing, {0.0, 0.0});
                addLayer(out, box, wall, f, depth, spacing, {0.5, 0.5});
            } else {
                addLayer(out, box, wall, f, depth, spacing, {0.5, 0.0});
                addLayer(out, box, wall, f, depth, spacing, {0.0, 0.5});
            }
        } else {
            addLayer(out, box, wall, f, depth, spacing, {plane % 2 == 0 ? 0.0 : 0.5, 0.0});
        }
    }
    return out;
}

}  // namespace

std::vector<Eigen::Vector3d> frozenLattice(const Box& box, const PlanarWallSettings& wall, const FrozenLatticeSettings& s) {
    const WallFrame f = frameOf(box, wall);
    if (s.thickness <= 0.0) throw std::invalid_argument("the wall thickness must be positive");
    if (s.lattice == "fcc" || s.lattice == "simpleCubic") {
        if (s.density <= 0.0) throw std::invalid_argument("the wall density must be positive");
        return cubicOrFcc(box, wall, f, s);
    }
    if (s.lattice != "layers") throw std::invalid_argument("unknown lattice '" + s.lattice + "' (expected fcc, simpleCubic or layers)");
    if (s.layerDepths.empty()) throw std::invalid_argument("the layers lattice needs 'layers' (depths behind the wall)");
    if (s.layerSpacing.size() != f.inPlane.size())
        throw std::invalid_argument("'spacing' needs " + std::to_string(f.inPlane.size()) +
                                    " value(s), one per in-plane axis");
    std::vector<double> spacing;
    for (std::size_t k = 0; k < f.inPlane.size(); ++k) {
        if (s.layerSpacing[k] <= 0.0) throw std::invalid_argument("'spacing' values must be positive");
        spacing.push_back(fittedSpacing(box.length()[f.inPlane[k]], s.layerSpacing[k]));
    }
    std::vector<Eigen::Vector3d> out;
    for (std::size_t k = 0; k < s.layerDepths.size(); ++k) {
        const double depth = s.layerDepths[k];
        if (depth < 0.0) throw std::invalid_argument("layer depths must not be negative (0 is on the wall, behind it positive)");
        // Staggered: the second, fourth... layer in the hollows of the one before, as in a close packing.
        const double shift = s.staggered && k % 2 == 1 ? 0.5 : 0.0;
        addLayer(out, box, wall, f, depth, spacing, {shift, shift});
    }
    return out;
}

}  // namespace dpd
