#include "io/Snapshot.hpp"

#include "core/Error.hpp"
#include "io/Hdf5File.hpp"
#include "io/SnapshotBonds.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <system_error>

namespace dpd {

namespace {

namespace fs = std::filesystem;

const std::string positionName = "particles/position";
const std::string velocityName = "particles/velocity";
const std::string forceName = "particles/force";
const std::string idName = "particles/id";
const std::string speciesName = "particles/species";
const std::string connectivityName = "xdmf/connectivity";

// ---------------------------------------------------------------------------------- writing --

// The arrays of a Particles are separate (structure of arrays); the file stores rows (x, y, z),
// which is what ParaView's XYZ geometry and numpy users expect.
std::vector<double> interleave(const ParticleArray<double>& x, const ParticleArray<double>& y,
                               const ParticleArray<double>& z) {
    std::vector<double> xyz(3 * x.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
        xyz[3 * i] = x[i];
        xyz[3 * i + 1] = y[i];
        xyz[3 * i + 2] = z[i];
    }
    return xyz;
}

void requireLength(std::size_t length, std::size_t n, const char* what) {
    if (length != n)
        throw std::invalid_argument("writeSnapshot: particle array '" + std::string(what) + "' has " +
                                    std::to_string(length) + " entries, expected " + std::to_string(n));
}

// A snapshot the reader would reject must not be written in the first place.
void checkConsistent(const Snapshot& s) {
    const Particles& p = s.particles;
    const std::size_t n = p.size();
    const std::vector<std::pair<const ParticleArray<double>*, const char*>> columns = {
        {&p.rx, "rx"}, {&p.ry, "ry"}, {&p.rz, "rz"}, {&p.vx, "vx"}, {&p.vy, "vy"},
        {&p.vz, "vz"}, {&p.fx, "fx"}, {&p.fy, "fy"}, {&p.fz, "fz"}};
    for (const auto& [column, name] : columns) requireLength(column->size(), n, name);
    requireLength(p.species.size(), n, "species");
    if (!s.speciesFrozen.empty() && s.speciesFrozen.size() != s.speciesNames.size())
        throw std::invalid_argument("writeSnapshot: speciesFrozen has " + std::to_string(s.speciesFrozen.size()) +
                                    " entries for " + std::to_string(s.speciesNames.size()) + " species");
    for (std::size_t i = 0; i < n; ++i)
        if (p.species[i] >= s.speciesNames.size())
            throw std::invalid_argument("writeSnapshot: particle " + std::to_string(p.id[i]) + " has species index " +
                                        std::to_string(p.species[i]) + " but only " +
                                        std::to_string(s.speciesNames.size()) + " species are named");
    checkBondsConsistent(s);
}

void writeParticleData(Hdf5Writer& file, const Particles& p) {
    const hsize_t n = p.size();
    file.writeDoubles(positionName, interleave(p.rx, p.ry, p.rz), {n, 3});
    file.writeDoubles(velocityName, interleave(p.vx, p.vy, p.vz), {n, 3});
    file.writeDoubles(forceName, interleave(p.fx, p.fy, p.fz), {n, 3});
    file.writeUInt64(idName, p.id.data(), p.id.size());
    file.writeInt32(speciesName, std::vector<std::int32_t>(p.species.begin(), p.species.end()));
}

bool connectivityFitsInt32(std::size_t n) {
    return n <= static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max());
}

// 32-bit indices halve the cost of this visualisation-only dataset; 64-bit only when needed.
void writeConnectivity(Hdf5Writer& file, std::size_t n) {
    if (connectivityFitsInt32(n)) {
        std::vector<std::int32_t> vertices(n);
        std::iota(vertices.begin(), vertices.end(), 0);
        file.writeInt32(connectivityName, vertices);
    } else {
        std::vector<std::int64_t> vertices(n);
        std::iota(vertices.begin(), vertices.end(), 0);
        file.writeInt64(connectivityName, vertices);
    }
}

std::vector<double> toVector(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

void writeRootAttributes(Hdf5Writer& file, const Snapshot& s) {
    std::vector<std::int64_t> frozen(s.speciesNames.size(), 0);
    for (std::size_t i = 0; i < s.speciesFrozen.size(); ++i) frozen[i] = s.speciesFrozen[i] ? 1 : 0;
    file.writeAttribute("/", "format", snapshotFormat);
    file.writeAttribute("/", "time", s.time);
    file.writeAttribute("/", "step", s.step);
    file.writeAttribute("/", "dimension", static_cast<std::int64_t>(s.box.dimension));
    file.writeAttribute("/", "boxLo", toVector(s.box.lo));
    file.writeAttribute("/", "boxHi", toVector(s.box.hi));
    file.writeAttribute("/", "speciesNames", s.speciesNames);
    file.writeAttribute("/", "speciesFrozen", frozen);
}

void writeHdf5(const fs::path& path, const Snapshot& s) {
    Hdf5Writer file(path.string());
    writeParticleData(file, s.particles);
    writeConnectivity(file, s.particles.size());
    writeBonds(file, s);
    writeRootAttributes(file, s);
    file.commit();
}

// Shortest decimal text that reads back as the same double: exact, yet "0.3" rather than
// "0.29999999999999999" in ParaView's time display.
std::string exactNumber(double value) {
    std::string text;
    for (int digits = 15; digits <= std::numeric_limits<double>::max_digits10; ++digits) {
        std::ostringstream out;
        out << std::setprecision(digits) << value;
        text = out.str();
        if (std::strtod(text.c_str(), nullptr) == value) break;
    }
    return text;
}

// One HDF DataItem; the file is named relative to the .xmf so a case directory can be moved.
std::string dataItem(const std::string& dims, const char* numberType, int precision, const std::string& dataset) {
    return "<DataItem Dimensions=\"" + dims + "\" NumberType=\"" + numberType + "\" Precision=\"" +
           std::to_string(precision) + "\" Format=\"HDF\">" + snapshotFileName + ":/" + dataset + "</DataItem>";
}

std::string xdmfAttribute(const char* name, const char* type, const std::string& item) {
    return std::string("      <Attribute Name=\"") + name + "\" AttributeType=\"" + type + "\" Center=\"Node\">\n" +
           "        " + item + "\n      </Attribute>\n";
}

// The bonds as line cells over the same positions, so ParaView draws the chains.
std::string xdmfBondGrid(const Snapshot& s) {
    const std::string m = std::to_string(s.bonds.size());
    const std::string n = std::to_string(s.particles.size());
    std::string text = "    <Grid Name=\"bonds\" GridType=\"Uniform\">\n";
    text += "      <Time Value=\"" + exactNumber(s.time) + "\"/>\n";
    text += "      <Topology TopologyType=\"Polyline\" NumberOfElements=\"" + m + "\" NodesPerElement=\"2\">\n";
    text += "        " + dataItem(m + " 2", "Int", 8, bondConnectivityName) + "\n      </Topology>\n";
    text += "      <Geometry GeometryType=\"XYZ\">\n";
    text += "        " + dataItem(n + " 3", "Float", 8, positionName) + "\n      </Geometry>\n";
    text += xdmfAttribute("chain", "Scalar", dataItem(n, "Int", 8, particleChainName));
    text += "    </Grid>\n";
    return text;
}

// Xdmf3 knows no unsigned 64-bit type, so ids are declared Int 8; HDF5 converts on reading, exact
// for every id below 2^63. Species are int32 in the file and declared so.
std::string xdmfText(const Snapshot& s) {
    const std::string n = std::to_string(s.particles.size());
    const std::string rows = n + " 3";
    const int connectivityPrecision = connectivityFitsInt32(s.particles.size()) ? 4 : 8;
    std::string text = "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n  <Domain>\n";
    text += "    <Grid Name=\"particles\" GridType=\"Uniform\">\n";
    text += "      <Time Value=\"" + exactNumber(s.time) + "\"/>\n";
    text += "      <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" + n + "\" NodesPerElement=\"1\">\n";
    text += "        " + dataItem(n, "Int", connectivityPrecision, connectivityName) + "\n      </Topology>\n";
    text += "      <Geometry GeometryType=\"XYZ\">\n";
    text += "        " + dataItem(rows, "Float", 8, positionName) + "\n      </Geometry>\n";
    text += xdmfAttribute("velocity", "Vector", dataItem(rows, "Float", 8, velocityName));
    text += xdmfAttribute("force", "Vector", dataItem(rows, "Float", 8, forceName));
    text += xdmfAttribute("species", "Scalar", dataItem(n, "Int", 4, speciesName));
    text += xdmfAttribute("id", "Scalar", dataItem(n, "Int", 8, idName));
    if (!s.bonds.empty()) text += xdmfAttribute("chain", "Scalar", dataItem(n, "Int", 8, particleChainName));
    text += "    </Grid>\n";
    if (!s.bonds.empty()) text += xdmfBondGrid(s);
    text += "  </Domain>\n</Xdmf>\n";
    return text;
}

void writeTextAtomically(const fs::path& path, const std::string& text) {
    const fs::path temporary = path.string() + ".tmp" + std::to_string(::getpid());
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        out << text;
        out.close();
        if (!out) {
            std::error_code ignored;
            fs::remove(temporary, ignored);
            throw IoError(path.string() + ": cannot write temporary file '" + temporary.string() + "'");
        }
    }
    std::error_code error;
    fs::rename(temporary, path, error);
    if (error) {
        fs::remove(temporary, error);
        throw IoError(path.string() + ": cannot rename '" + temporary.string() + "' to it");
    }
}

// ---------------------------------------------------------------------------------- reading --

[[noreturn]] void fail(const Hdf5Reader& file, const std::string& message) {
    throw IoError(file.path() + ": " + message);
}

std::string shapeText(const std::vector<hsize_t>& dims) {
    std::string s = "(";
    for (std::size_t i = 0; i < dims.size(); ++i) s += (i ? ", " : "") + std::to_string(dims[i]);
    return s + ")";
}

void requireShape(const Hdf5Reader& file, const std::string& name, const std::vector<hsize_t>& actual,
                  const std::vector<hsize_t>& expected) {
    if (actual != expected)
        fail(file, "dataset '" + name + "' has shape " + shapeText(actual) + ", expected " + shapeText(expected));
}

void requireFormat(const Hdf5Reader& file) {
    const std::string format = file.attributeString("/", "format");
    if (format != snapshotFormat)
        fail(file, "attribute 'format' is '" + format + "', expected '" + snapshotFormat + "'");
}

Eigen::Vector3d readCorner(const Hdf5Reader& file, const char* name) {
    const std::vector<double> v = file.attributeDoubles("/", name);
    if (v.size() != 3)
        fail(file, "attribute '" + std::string(name) + "' has " + std::to_string(v.size()) + " values, expected 3");
    for (double x : v)
        if (!std::isfinite(x)) fail(file, "attribute '" + std::string(name) + "' holds a value that is not finite");
    return {v[0], v[1], v[2]};
}

Box readBox(const Hdf5Reader& file) {
    Box box;
    const std::int64_t dimension = file.attributeInt("/", "dimension");
    if (dimension != 2 && dimension != 3)
        fail(file, "attribute 'dimension' is " + std::to_string(dimension) + ", expected 2 or 3");
    box.dimension = static_cast<int>(dimension);
    box.lo = readCorner(file, "boxLo");
    box.hi = readCorner(file, "boxHi");
    for (int axis = 0; axis < 3; ++axis)
        if (box.isActiveAxis(axis) && !(box.hi[axis] > box.lo[axis]))
            fail(file, "attributes 'boxLo'/'boxHi' give an empty box along axis " + std::to_string(axis));
    return box;
}

void readSpecies(const Hdf5Reader& file, Snapshot& s) {
    s.speciesNames = file.attributeStrings("/", "speciesNames");
    // Accept integers or floating-point flags: files written by hand (h5py) may use either.
    const std::vector<double> frozen = file.attributeDoubles("/", "speciesFrozen");
    if (frozen.size() != s.speciesNames.size())
        fail(file, "attribute 'speciesFrozen' has " + std::to_string(frozen.size()) + " values for " +
                       std::to_string(s.speciesNames.size()) + " species");
    s.speciesFrozen.clear();
    for (double f : frozen) s.speciesFrozen.push_back(f != 0.0);
}

void splitRows(const std::vector<double>& xyz, ParticleArray<double>& x, ParticleArray<double>& y,
               ParticleArray<double>& z) {
    const std::size_t n = xyz.size() / 3;
    x.resize(n);
    y.resize(n);
    z.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        x[i] = xyz[3 * i];
        y[i] = xyz[3 * i + 1];
        z[i] = xyz[3 * i + 2];
    }
}

// Reads one (n, 3) dataset into three columns.
void readRows(const Hdf5Reader& file, const std::string& name, std::size_t n, ParticleArray<double>& x,
              ParticleArray<double>& y, ParticleArray<double>& z) {
    std::vector<hsize_t> dims;
    const std::vector<double> xyz = file.readDoubles(name, &dims);
    requireShape(file, name, dims, {static_cast<hsize_t>(n), 3});
    splitRows(xyz, x, y, z);
}

void readSpeciesIndices(const Hdf5Reader& file, std::size_t n, std::size_t nSpecies, Particles& p) {
    std::vector<hsize_t> dims;
    const std::vector<std::int32_t> species = file.readInt32(speciesName, &dims);
    requireShape(file, speciesName, dims, {static_cast<hsize_t>(n)});
    p.species.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        // Particles stores indices as uint8, hence the second bound.
        if (species[i] < 0 || static_cast<std::size_t>(species[i]) >= nSpecies || species[i] > 255)
            fail(file, "dataset '" + speciesName + "' holds species index " + std::to_string(species[i]) +
                           " at row " + std::to_string(i) + ", but " + std::to_string(nSpecies) +
                           " species are named");
        p.species[i] = static_cast<std::uint8_t>(species[i]);
    }
}

std::string cornerText(const Eigen::Vector3d& r) {
    std::ostringstream os;
    os << "(" << r.x() << " " << r.y() << " " << r.z() << ")";
    return os.str();
}

std::string rowText(const ParticleArray<double>& x, const ParticleArray<double>& y, const ParticleArray<double>& z,
                    std::size_t i) {
    std::ostringstream os;
    os << std::setprecision(10) << "(" << x[i] << " " << y[i] << " " << z[i] << ")";
    return os.str();
}

// Every value of an (n, 3) dataset is a finite number.
void requireFinite(const Hdf5Reader& file, const std::string& name, const ParticleArray<double>& x,
                   const ParticleArray<double>& y, const ParticleArray<double>& z) {
    for (std::size_t i = 0; i < x.size(); ++i)
        if (!std::isfinite(x[i]) || !std::isfinite(y[i]) || !std::isfinite(z[i]))
            fail(file, "dataset '" + name + "' row " + std::to_string(i) + " holds " + rowText(x, y, z, i) +
                           ": not a finite number");
}

// A position may lie outside the box (it is wrapped), but by less than one box length: further out
// it is a corrupted or mistaken value, not a particle that left the box during a step.
void requireNearBox(const Hdf5Reader& file, const Box& box, const Particles& p) {
    const Eigen::Vector3d lo = box.lo - box.length(), hi = box.hi + box.length();
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double r[3] = {p.rx[i], p.ry[i], p.rz[i]};
        for (int a = 0; a < 3; ++a)
            if (box.isActiveAxis(a) && !(r[a] >= lo[a] && r[a] <= hi[a]))
                fail(file, "dataset '" + positionName + "' row " + std::to_string(i) + " holds " +
                               rowText(p.rx, p.ry, p.rz, i) + ": more than one box length outside the box " +
                               cornerText(box.lo) + " - " + cornerText(box.hi));
    }
}

void requireUniqueIds(const Hdf5Reader& file, const Particles& p) {
    std::vector<std::pair<std::uint64_t, std::size_t>> ids(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) ids[i] = {p.id[i], i};
    std::sort(ids.begin(), ids.end());
    for (std::size_t k = 1; k < ids.size(); ++k)
        if (ids[k].first == ids[k - 1].first)
            fail(file, "dataset '" + idName + "' holds id " + std::to_string(ids[k].first) + " twice (rows " +
                           std::to_string(ids[k - 1].second) + " and " + std::to_string(ids[k].second) + ")");
}

void readParticles(const Hdf5Reader& file, std::size_t nSpecies, Particles& p) {
    // The position dataset fixes N; every other dataset must agree with it.
    std::vector<hsize_t> dims;
    const std::vector<double> position = file.readDoubles(positionName, &dims);
    if (dims.size() != 2 || dims[1] != 3)
        fail(file, "dataset '" + positionName + "' has shape " + shapeText(dims) + ", expected (N, 3)");
    const std::size_t n = static_cast<std::size_t>(dims[0]);
    splitRows(position, p.rx, p.ry, p.rz);
    readRows(file, velocityName, n, p.vx, p.vy, p.vz);
    readRows(file, forceName, n, p.fx, p.fy, p.fz);
    const std::vector<std::uint64_t> ids = file.readUInt64(idName, &dims);
    p.id.assign(ids.begin(), ids.end());
    requireShape(file, idName, dims, {static_cast<hsize_t>(n)});
    readSpeciesIndices(file, n, nSpecies, p);
    requireFinite(file, positionName, p.rx, p.ry, p.rz);
    requireFinite(file, velocityName, p.vx, p.vy, p.vz);
    requireFinite(file, forceName, p.fx, p.fy, p.fz);
    requireUniqueIds(file, p);
}

}  // namespace

void writeSnapshot(const std::string& timeDir, const Snapshot& s) {
    checkConsistent(s);
    const fs::path dir(timeDir);
    std::error_code error;
    fs::create_directories(dir, error);
    if (error) throw IoError(timeDir + ": cannot create directory: " + error.message());
    writeHdf5(dir / snapshotFileName, s);
    writeTextAtomically(dir / snapshotXdmfFileName, xdmfText(s));
}

Snapshot readSnapshot(const std::string& h5File) {
    const Hdf5Reader file(h5File);
    requireFormat(file);
    Snapshot s;
    s.time = file.attributeDouble("/", "time");
    if (!(std::isfinite(s.time) && s.time >= 0.0)) fail(file, "attribute 'time' is " + std::to_string(s.time));
    s.step = file.attributeInt("/", "step");
    if (s.step < 0) fail(file, "attribute 'step' is " + std::to_string(s.step));
    s.box = readBox(file);
    readSpecies(file, s);
    readParticles(file, s.speciesNames.size(), s.particles);
    requireNearBox(file, s.box, s.particles);
    readBonds(file, s);
    return s;
}

}  // namespace dpd
