#include "geometry/GmshGeometry.hpp"

#include "core/Axis.hpp"
#include "geometry/BucketGrid.hpp"
#include "geometry/GeometryInputError.hpp"

#include <gmsh.h>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <omp.h>

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <filesystem>
#include <map>
#include <mutex>
#include <unordered_map>

namespace dpd {

namespace {

[[noreturn]] void fail(const std::string& file, const std::string& message) {
    throw GeometryInputError("file", file + ": " + message);
}

// Triangles or tetrahedra in geometry coordinates, with the inverse of each one's edge matrix so
// that barycentric coordinates cost one matrix-vector product.
struct SimplexMesh {
    int dimension = 2;
    std::vector<Eigen::Vector3d> vertices;
    std::vector<std::array<int, 4>> simplices;   // vertex indices (the fourth unused for triangles)
    std::vector<Eigen::Matrix3d> inverse;
    BucketGrid buckets;

    bool contains(std::size_t s, const Eigen::Vector3d& p) const {
        constexpr double tol = 1e-9;
        const Eigen::Vector3d l = inverse[s] * (p - vertices[simplices[s][0]]);
        double sum = 0.0;
        for (int k = 0; k < dimension; ++k) {
            if (l[k] < -tol) return false;
            sum += l[k];
        }
        return sum <= 1.0 + tol;
    }
    bool containsPoint(const Eigen::Vector3d& p) const {
        bool inside = false;
        buckets.forEachNear(p, 0.0, [&](std::uint32_t s) { inside = inside || contains(s, p); });
        return inside;
    }
};

// gmsh is one global state: one thread at a time, and a fresh start for every file, since a file
// that fails to parse leaves gmsh 4.8 unable to read the next one.
std::mutex& gmshMutex() {
    static std::mutex m;
    return m;
}

// gmsh sets OpenMP's thread count for the whole process (General.NumThreads, 1 by default): the
// session gives the caller's count back, or a run that reads a gmsh geometry would go on one thread.
struct GmshSession {
    GmshSession() : threads(omp_get_max_threads()) {
        gmsh::initialize(0, nullptr, false);
        gmsh::option::setNumber("General.Terminal", 0);
    }
    ~GmshSession() {
        gmsh::finalize();
        omp_set_num_threads(threads);
    }
    int threads;
    GmshSession(const GmshSession&) = delete;
    GmshSession& operator=(const GmshSession&) = delete;
};

void openWithGmsh(const std::string& file) {
    try {
        gmsh::open(file);
    } catch (const std::string& e) {
        fail(file, "gmsh cannot read it: " + e);
    } catch (const std::exception& e) {
        fail(file, std::string("gmsh cannot read it: ") + e.what());
    }
    std::string error;
    gmsh::logger::getLastError(error);
    if (!error.empty()) fail(file, "gmsh cannot read it: " + error);
}

std::pair<int, int> regionGroup(const std::string& file, bool& groupIsFluid) {
    gmsh::vectorpair groups;
    gmsh::model::getPhysicalGroups(groups);
    std::vector<std::pair<int, int>> found;
    for (const auto& [dim, tag] : groups) {
        std::string name;
        gmsh::model::getPhysicalName(dim, tag, name);
        if (name == "fluid" || name == "solid") {
            found.emplace_back(dim, tag);
            groupIsFluid = name == "fluid";
        }
    }
    if (found.empty())
        fail(file, "no physical group named \"fluid\" or \"solid\" (e.g. Physical Surface(\"fluid\") = {1};)");
    if (found.size() > 1) fail(file, "give only one physical group named \"fluid\" or \"solid\"");
    if (found[0].first < 2) fail(file, "the \"fluid\"/\"solid\" group must be a surface or a volume");
    return found[0];
}

struct RawElements {
    std::vector<std::size_t> nodeTags;   // `corners` per simplex
    int corners = 0;
};

RawElements groupSimplices(const std::string& file, int dim, int tag) {
    RawElements raw;
    raw.corners = dim + 1;
    std::vector<int> entities;
    gmsh::model::getEntitiesForPhysicalGroup(dim, tag, entities);
    for (const int entity : entities) {
        std::vector<int> types;
        std::vector<std::vector<std::size_t>> elementTags, nodeTags;
        gmsh::model::mesh::getElements(types, elementTags, nodeTags, dim, entity);
        for (std::size_t t = 0; t < types.size(); ++t) {
            std::string name;
            int eDim = 0, order = 0, numNodes = 0, numPrimary = 0;
            std::vector<double> local;
            gmsh::model::mesh::getElementProperties(types[t], name, eDim, order, numNodes, local, numPrimary);
            const bool triangle = dim == 2 && numPrimary == 3, quad = dim == 2 && numPrimary == 4,
                       tet = dim == 3 && numPrimary == 4;
            if (!triangle && !quad && !tet)
                fail(file, "elements of type '" + name + "' are not supported (triangles, quadrangles or tetrahedra)");
            const auto& n = nodeTags[t];
            for (std::size_t e = 0; e + numNodes <= n.size(); e += numNodes) {
                if (quad) {  // two triangles
                    raw.nodeTags.insert(raw.nodeTags.end(), {n[e], n[e + 1], n[e + 2], n[e], n[e + 2], n[e + 3]});
                } else {
                    raw.nodeTags.insert(raw.nodeTags.end(), n.begin() + e, n.begin() + e + numPrimary);
                }
            }
        }
    }
    return raw;
}

SimplexMesh buildMesh(const std::string& file, const RawElements& raw, const GeometryFrame& frame) {
    SimplexMesh mesh;
    mesh.dimension = raw.corners - 1;
    std::vector<std::size_t> tags;
    std::vector<double> coords, parametric;
    gmsh::model::mesh::getNodes(tags, coords, parametric, -1, -1, false, false);
    std::unordered_map<std::size_t, int> indexOfTag;
    for (std::size_t k = 0; k < tags.size(); ++k) {
        indexOfTag[tags[k]] = static_cast<int>(k);
        Eigen::Vector3d p(coords[3 * k], coords[3 * k + 1], mesh.dimension == 3 ? coords[3 * k + 2] : 0.0);
        mesh.vertices.push_back(p);
    }
    double measure = 0.0;
    for (std::size_t e = 0; e < raw.nodeTags.size(); e += raw.corners) {
        std::array<int, 4> s{0, 0, 0, 0};
        for (int c = 0; c < raw.corners; ++c) s[c] = indexOfTag.at(raw.nodeTags[e + c]);
        Eigen::Matrix3d edges = Eigen::Matrix3d::Identity();
        for (int c = 1; c < raw.corners; ++c) edges.col(c - 1) = mesh.vertices[s[c]] - mesh.vertices[s[0]];
        const double det = edges.determinant();
        if (std::abs(det) < 1e-14) continue;  // degenerate: covers no area
        measure += std::abs(det) / (mesh.dimension == 3 ? 6.0 : 2.0);
        mesh.simplices.push_back(s);
        mesh.inverse.push_back(edges.inverse());
    }
    if (mesh.simplices.empty()) fail(file, "the \"fluid\"/\"solid\" group has no elements after meshing");
    // A plain maximum: Eigen's vectorised maxCoeff over a dynamic block trips GCC 12's
    // -Wmaybe-uninitialized inside its AVX-512 intrinsics.
    const double tol = 1e-6 * std::max(frame.period[0], mesh.dimension == 3 ? std::max(frame.period[1], frame.period[2]) : frame.period[1]);
    for (const auto& s : mesh.simplices)
        for (int c = 0; c < raw.corners; ++c)
            for (int a = 0; a < mesh.dimension; ++a) {
                const double x = mesh.vertices[s[c]][a];
                if (x < frame.localLo[a] - tol || x > frame.localLo[a] + frame.period[a] + tol)
                    fail(file, std::string("the mesh reaches ") + axisLetter(a) + " = " + std::to_string(x) +
                                   " (gmsh coordinates), outside the box (check origin and the box size)");
            }
    // Buckets about two elements wide.
    const double elementSize = std::pow(measure / mesh.simplices.size(), 1.0 / mesh.dimension);
    mesh.buckets = BucketGrid(mesh.dimension, frame.localLo, frame.period, 2.0 * elementSize);
    for (std::size_t k = 0; k < mesh.simplices.size(); ++k) {
        Eigen::Vector3d lo = mesh.vertices[mesh.simplices[k][0]], hi = lo;
        for (int c = 1; c < raw.corners; ++c) {
            lo = lo.cwiseMin(mesh.vertices[mesh.simplices[k][c]]);
            hi = hi.cwiseMax(mesh.vertices[mesh.simplices[k][c]]);
        }
        mesh.buckets.add(static_cast<std::uint32_t>(k), lo, hi);
    }
    mesh.buckets.build();
    return mesh;
}

// The facets of the group's elements that only one element has, with the normal into that element.
void addBoundary(const SimplexMesh& mesh, const GeometryFrame& frame, bool groupIsFluid, BoundaryFacets& facets) {
    struct Face {
        int count = 0;
        std::size_t simplex = 0;
        int opposite = 0;   // the corner not on the face
    };
    std::map<std::array<int, 3>, Face> faces;
    const int corners = mesh.dimension + 1;
    for (std::size_t s = 0; s < mesh.simplices.size(); ++s)
        for (int skip = 0; skip < corners; ++skip) {
            // The face's vertices in increasing order (an unused third slot sorts last).
            std::array<int, 3> key{INT_MAX, INT_MAX, INT_MAX};
            for (int c = 0, k = 0; c < corners; ++c)
                if (c != skip) key[k++] = mesh.simplices[s][c];
            std::sort(key.begin(), key.end());
            Face& f = faces[key];
            ++f.count;
            f.simplex = s;
            f.opposite = mesh.simplices[s][skip];
        }
    const auto wrapLocal = [&](const Eigen::Vector3d& p) { return frame.toLocal(frame.origin + frame.toBoxVector(p)); };
    for (const auto& [key, f] : faces) {
        if (f.count != 1) continue;
        const Eigen::Vector3d& a = mesh.vertices[key[0]];
        const Eigen::Vector3d& b = mesh.vertices[key[1]];
        const Eigen::Vector3d c = mesh.dimension == 3 ? mesh.vertices[key[2]] : b;
        Eigen::Vector3d n = mesh.dimension == 3 ? Eigen::Vector3d((b - a).cross(c - a))
                                                : Eigen::Vector3d(a.y() - b.y(), b.x() - a.x(), 0.0);
        n.normalize();
        const Eigen::Vector3d centroid = mesh.dimension == 3 ? Eigen::Vector3d((a + b + c) / 3.0) : Eigen::Vector3d(0.5 * (a + b));
        if (n.dot(mesh.vertices[f.opposite] - centroid) < 0.0) n = -n;   // into the group's element
        // On the box boundary the group may continue through the periodic face: then no surface.
        const double eps = 1e-7 * (b - a).norm();
        if (mesh.containsPoint(wrapLocal(centroid - eps * n))) continue;
        const Eigen::Vector3d intoFluid = groupIsFluid ? n : Eigen::Vector3d(-n);
        if (mesh.dimension == 3) facets.addTriangle(a, b, c, intoFluid);
        else facets.addSegment(a, b, intoFluid);
    }
}

}  // namespace

SolidGeometry gmshGeometry(const GmshSettings& s, const Box& box, double searchReach) {
    if (!std::filesystem::is_regular_file(s.file)) fail(s.file, "no such gmsh file");
    const std::lock_guard<std::mutex> lock(gmshMutex());
    const GmshSession session;
    openWithGmsh(s.file);
    bool groupIsFluid = true;
    const auto [dim, tag] = regionGroup(s.file, groupIsFluid);
    if (dim == 3 && box.dimension == 2) fail(s.file, "a volume geometry needs a 3-D box (dimension 3)");
    RawElements raw = groupSimplices(s.file, dim, tag);
    if (raw.nodeTags.empty()) {
        if (s.meshSize > 0.0) gmsh::option::setNumber("Mesh.MeshSizeMax", s.meshSize);
        // Plain Delaunay for surfaces: gmsh 4.8's default Frontal-Delaunay corrupted the heap on
        // the side faces of an extruded volume (tests/geometry/GmshGeometryTest, 3-D channel).
        gmsh::option::setNumber("Mesh.Algorithm", 5);
        try {
            gmsh::model::mesh::generate(dim);
        } catch (const std::string& e) {
            fail(s.file, "gmsh cannot mesh it: " + e);
        }
        raw = groupSimplices(s.file, dim, tag);
    }
    const GeometryFrame frame = dim == 3 ? GeometryFrame::spatial(box, s.origin) : GeometryFrame::planar(box, s.extrudeAxis, s.origin);
    auto mesh = std::make_shared<SimplexMesh>(buildMesh(s.file, raw, frame));
    BoundaryFacets facets(frame);
    addBoundary(*mesh, frame, groupIsFluid, facets);
    return SolidGeometry(
        frame, [mesh, groupIsFluid](const Eigen::Vector3d& p) { return mesh->containsPoint(p) != groupIsFluid; },
        std::move(facets), s.file, searchReach);
}

}  // namespace dpd
