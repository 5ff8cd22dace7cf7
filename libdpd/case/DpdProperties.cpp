#include "case/DpdProperties.hpp"

#include "case/CaseSlipCalibrations.hpp"
#include "case/RunCompatibility.hpp"

#include "geometry/GeometryDictionary.hpp"

#include "core/Error.hpp"
#include "io/Dictionary.hpp"
#include "io/Snapshot.hpp"
#include "system/System.hpp"
#include "walls/GeometryWallDictionary.hpp"
#include "walls/WallTypes.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

namespace dpd {

namespace {

SpeciesTable readSpecies(const Dictionary& d) {
    const Dictionary& sd = d.subDict("species");
    SpeciesTable table;
    for (const std::string& name : sd.keys()) {
        if (!sd.isDict(name)) sd.fail(name, "each species is a sub-dictionary, e.g. fluid { frozen no; }");
        if (name.find('-') != std::string::npos) sd.fail(name, "a species name may not contain '-'");
        const Dictionary& s = sd.subDict(name);
        s.checkKeys({"frozen"});
        table.add({name, s.getOrDefault<bool>("frozen", false)});
    }
    if (table.size() == 0) d.fail("species", "at least one species is needed");
    if (table.size() > 255) d.fail("species", "at most 255 species");
    return table;
}

// One pair entry: { a ..; gamma ..; }, where `a` may be left out to be mixed from the like pairs.
struct PairEntry {
    bool given = false;
    bool hasA = false;
    PairCoeffs coeffs;
};

// Mixing rule (docs/methods.md section 1): a pair not given, or given without `a`, takes
// a_ij = sqrt(a_ii a_jj) from the like pairs (and, when not given at all, gamma_ij = sqrt(gamma_ii
// gamma_jj), which is the common gamma when the like pairs share one). Each use goes into `notes`.
void mixPair(const Dictionary& d, const SpeciesTable& species, const std::vector<PairEntry>& entries, int a, int b,
             PairTable& table, std::vector<std::string>& notes) {
    const int n = species.size();
    const PairEntry& e = entries[a * n + b];
    const PairEntry& aa = entries[a * n + a];
    const PairEntry& bb = entries[b * n + b];
    const std::string name = species[a].name + "-" + species[b].name;
    if (!(aa.hasA && bb.hasA))
        d.fail("pairCoeffs", "no coefficient a for the pair " + name + ": give " + name + " { a ...; gamma ...; }, or both " +
                                 species[a].name + "-" + species[a].name + " and " + species[b].name + "-" +
                                 species[b].name + " so that a is mixed as sqrt(a_" + species[a].name + " a_" +
                                 species[b].name + ")");
    if (aa.coeffs.a < 0.0 || bb.coeffs.a < 0.0)
        d.fail("pairCoeffs", "cannot mix a for the pair " + name + ": the like pairs have a negative a");
    PairCoeffs c = e.coeffs;
    c.a = std::sqrt(aa.coeffs.a * bb.coeffs.a);
    std::ostringstream note;
    note << name << ": a = sqrt(" << aa.coeffs.a << " x " << bb.coeffs.a << ") = " << c.a;
    if (!e.given) {
        c.gamma = std::sqrt(aa.coeffs.gamma * bb.coeffs.gamma);
        note << ", gamma = sqrt(" << aa.coeffs.gamma << " x " << bb.coeffs.gamma << ") = " << c.gamma;
    }
    notes.push_back(note.str() + " (mixed)");
    table.set(a, b, c);
}

PairTable readPairs(const Dictionary& d, const SpeciesTable& species, std::vector<std::string>& notes) {
    const Dictionary& pd = d.subDict("pairCoeffs");
    const int n = species.size();
    PairTable table(n);
    std::vector<PairEntry> entries(n * n);
    for (const std::string& key : pd.keys()) {
        const auto dash = key.find('-');
        const int a = dash == std::string::npos ? -1 : species.indexOf(key.substr(0, dash));
        const int b = dash == std::string::npos ? -1 : species.indexOf(key.substr(dash + 1));
        if (a < 0 || b < 0) pd.fail(key, "expected <species>-<species> with species from the 'species' dictionary");
        if (!pd.isDict(key)) pd.fail(key, "expected a sub-dictionary { a ...; gamma ...; }");
        const Dictionary& c = pd.subDict(key);
        c.checkKeys({"a", "gamma"});
        PairEntry e;
        e.given = true;
        e.hasA = c.found("a");
        if (a == b && !e.hasA) c.fail("a", "a like pair needs its a (only unlike pairs can be mixed)");
        e.coeffs = {e.hasA ? c.get<double>("a") : 0.0, c.getNonNegative<double>("gamma"), 0.0, true};
        entries[a * n + b] = entries[b * n + a] = e;
        table.set(a, b, e.coeffs);
    }
    for (int a = 0; a < n; ++a)
        for (int b = a; b < n; ++b) {
            const PairEntry& e = entries[a * n + b];
            if (e.given && e.hasA) continue;
            if (species[a].frozen && species[b].frozen) continue;  // never interact
            if (a == b) d.fail("pairCoeffs", "no coefficients for the pair " + species[a].name + "-" + species[b].name);
            mixPair(d, species, entries, a, b, table, notes);
        }
    return table;
}

IntegratorSettings readIntegrator(const Dictionary& d) {
    return d.found("integrator") ? IntegratorSettings::read(d.subDict("integrator")) : IntegratorSettings{};
}

// The case's geometry block, kept for a geometry wall to be built on the snapshot's box (null: none).
std::shared_ptr<const Dictionary> geometryBlock(const Dictionary& d) {
    return d.found("geometry") ? std::make_shared<const Dictionary>(d.subDict("geometry")) : nullptr;
}

// Each wall names its type (walls/WallTypes.hpp), which reads the rest of its sub-dictionary.
// slipLengths: what a wall that asks for a slip length is resolved against (null: such a wall is refused).
WallList readWalls(const Dictionary& d, DpdModel& m, const SlipLengthResolver* slipLengths) {
    const int dimension = m.dimension;
    const double cutoff = m.cutoff;
    WallList walls;
    if (!d.found("walls")) return walls;
    const Dictionary& wd = d.subDict("walls");
    const std::shared_ptr<const Dictionary> geometry = geometryBlock(d);  // one copy shared by the walls
    for (const std::string& name : wd.keys()) {
        if (!wd.isDict(name)) wd.fail(name, "each wall is a sub-dictionary");
        const Dictionary& w = wd.subDict(name);
        const std::string type = w.get<std::string>("type");
        if (!wallRegistry().has(type))
            w.fail("type", "unknown wall type '" + type + "' (expected " + wallRegistry().nameList() + ")");
        walls.add(wallRegistry().make(type, w, WallReadContext{name, walls.size(), dimension, cutoff, geometry,
                                                               &m.planarWalls, slipLengths, &m.wallNotes}));
    }
    return walls;
}

bool hasGeometryWall(const Dictionary& d) {
    if (!d.found("walls")) return false;
    const Dictionary& wd = d.subDict("walls");
    for (const std::string& name : wd.keys())
        if (wd.subDict(name).getOrDefault<std::string>("type", "") == "geometry") return true;
    return false;
}

// A geometry block without a geometry wall in the walls block gets one, named geometry: its rule from
// the older geometryWall block (read with a note), else bounceBack.
void addGeometryWall(const Dictionary& d, int dimension, double cutoff, DpdModel& m) {
    if (!d.found("geometry")) {
        if (d.found("geometryWall")) d.fail("geometryWall", "a geometryWall needs the geometry block it acts on");
        return;
    }
    const bool declared = hasGeometryWall(d);
    if (declared && d.found("geometryWall"))
        d.fail("geometryWall", "the walls block has a geometry wall already: give its rule there");
    if (declared) return;
    const WallReadContext context{"geometry", m.walls.size(), dimension, cutoff, geometryBlock(d)};
    if (d.found("geometryWall")) {
        m.walls.add(readGeometryWall(d.subDict("geometryWall"), context));
        m.inputNotes.push_back("geometryWall { ... } is read as walls { geometry { type geometry; ... } }, its newer form");
        return;
    }
    m.walls.add(readGeometryWall(Dictionary::parse("type geometry;", "constant/dpdProperties geometry wall"), context));
}

StabilitySettings readStability(const Dictionary& d) {
    StabilitySettings s;
    if (!d.found("stability")) return s;
    const Dictionary& sd = d.subDict("stability");
    sd.checkKeys({"maxKTRatio", "maxInsideWalls", "checkInterval"});
    s.maxKTRatio = sd.getOrDefault<double>("maxKTRatio", s.maxKTRatio);
    if (s.maxKTRatio <= 1.0) sd.fail("maxKTRatio", "must be greater than 1");
    s.maxInsideWalls = sd.getOrDefault<long>("maxInsideWalls", s.maxInsideWalls);
    if (s.maxInsideWalls < 0) sd.fail("maxInsideWalls", "must not be negative");
    if (sd.found("checkInterval")) s.checkIntervalSteps = sd.getPositive<long>("checkInterval");
    return s;
}

// Mobile particles inside a wall's solid at the start are a mistaken state (walls return only what
// crosses during a step): more than the run itself tolerates (stability maxInsideWalls) are refused.
void requireFewInsideWalls(const System& sys, const DpdModel& model, const std::string& snapshotFile) {
    long inside = 0;
    for (std::size_t i = 0; i < sys.particles.size(); ++i) {
        if (model.species[sys.particles.species[i]].frozen) continue;
        Eigen::Vector3d r(sys.particles.rx[i], sys.particles.ry[i], sys.particles.rz[i]);
        sys.box.wrapPoint(r.x(), r.y(), r.z());
        for (std::size_t w = 0; w < sys.walls.size(); ++w) {
            if (!sys.walls[w].isInsideSolid(r)) continue;
            if (++inside <= model.stability.maxInsideWalls) break;
            std::ostringstream os;
            os << snapshotFile << ": dataset 'particles/position' row " << i << " holds (" << r.x() << " " << r.y()
               << " " << r.z() << "), a mobile particle inside the solid of wall '" << sys.walls[w].name() << "' ("
               << -sys.walls[w].signedDistance(r) << " deep); " << inside << " such particle(s) so far, stability "
               << "maxInsideWalls allows " << model.stability.maxInsideWalls;
            throw IoError(os.str());
        }
    }
}

// The snapshot's bonds, with the model's spring; only mobile particles, every bond shorter than the
// spring allows.
void addBonds(System& sys, const DpdModel& model, Bonds bonds, const std::string& snapshotFile) {
    if (bonds.empty()) return;
    if (!model.bondPotential)
        throw IoError(snapshotFile + " holds " + std::to_string(bonds.size()) +
                      " bonds but constant/dpdProperties has no bonds block (e.g. bonds { type FENE; H 6; rMax 3; })");
    const double maxLength = model.bondPotential->maxLength();
    for (std::size_t k = 0; k < bonds.size(); ++k)
        if (!(bonds.vector(k).norm() < maxLength))
            throw IoError(snapshotFile + ": dataset 'bonds/vector' row " + std::to_string(k) + " is a bond of length " +
                          std::to_string(bonds.vector(k).norm()) + ", not shorter than the bonds' rMax " + std::to_string(maxLength));
    sys.bonds = ChainBonds(std::move(bonds));
    sys.bondPotential = model.bondPotential;
    sys.bondedPairs = model.bondedPairs;
    sys.bonds.locate(sys.particles);
    const Bonds& b = sys.bonds.bonds();
    for (std::size_t k = 0; k < b.size(); ++k)
        for (std::uint64_t id : {b.first[k], b.second[k]})
            if (model.species[sys.particles.species[sys.bonds.indexOf(id)]].frozen)
                throw IoError(snapshotFile + ": particle " + std::to_string(id) + " is bonded but of a frozen species");
}

}  // namespace

std::vector<const PlanarWallSettings*> DpdModel::planes() const {
    std::vector<const PlanarWallSettings*> p;
    for (const PlanarWallSettings& w : planarWalls) p.push_back(&w);
    return p;
}

namespace {

// caseDir null: no case, so a wall that asks for a slip length is refused.
DpdModel readModel(const Dictionary& d, const std::string* caseDir) {
    // geometry: the solid of any shape, read where it is used (geometry/GeometryDictionary).
    d.checkKeys({"dimension", "kT", "cutoff", "seed", "weightExponent", "species", "pairCoeffs", "integrator",
                 "bodyForce", "bonds", "walls", "stability", "geometry", "geometryWall"});
    DpdModel m;
    m.dimension = d.getOrDefault<int>("dimension", 3);
    if (m.dimension != 2 && m.dimension != 3) d.fail("dimension", "must be 2 or 3");
    m.kT = d.getPositive<double>("kT");
    m.cutoff = d.found("cutoff") ? d.getPositive<double>("cutoff") : 1.0;
    m.weightExponent = d.found("weightExponent") ? d.getPositive<double>("weightExponent") : 2.0;
    const long seed = d.getOrDefault<long>("seed", 1);
    if (seed < 0) d.fail("seed", "must not be negative");
    m.seed = static_cast<std::uint64_t>(seed);
    m.species = readSpecies(d);
    m.pairs = readPairs(d, m.species, m.pairNotes);
    m.integrator = readIntegrator(d);
    m.bodyForce = readBodyForce(d, m.dimension);  // forces/BodyForceTypes.cpp
    m.bondPotential = readBondPotential(d);         // forces/BondPotentialTypes.cpp
    if (m.bondPotential) m.bondedPairs = BondedPairs::read(d.subDict("bonds"));
    if (caseDir) {
        const CaseSlipCalibrations calibrations(m, d, *caseDir);
        m.walls = readWalls(d, m, &calibrations);
    } else {
        m.walls = readWalls(d, m, nullptr);
    }
    addGeometryWall(d, m.dimension, m.cutoff, m);
    checkCompatibility(caseParts(m));  // the integrator refuses what it cannot run
    m.stability = readStability(d);
    return m;
}

}  // namespace

DpdModel readDpdModel(const Dictionary& d) { return readModel(d, nullptr); }

DpdModel readDpdModel(const Dictionary& d, const std::string& caseDir) {
    DpdModel m = readModel(d, &caseDir);
    m.caseDir = caseDir;
    return m;
}

DpdModel readDpdProperties(const std::string& caseDir) {
    return readDpdModel(Dictionary::readFile((std::filesystem::path(caseDir) / "constant" / "dpdProperties").string()),
                        caseDir);
}

System buildSystem(const DpdModel& model, Snapshot snapshot, double dt, const std::string& snapshotFile,
                   const Communicator* ranks, const std::vector<int>& slabPlanes) {
    if (snapshot.box.dimension != model.dimension)
        throw IoError(snapshotFile + ": the snapshot is " + std::to_string(snapshot.box.dimension) +
                      "-D but constant/dpdProperties says dimension " + std::to_string(model.dimension));
    // Map the snapshot's species numbering onto the model's, by name.
    std::vector<std::uint8_t> map(snapshot.speciesNames.size());
    for (std::size_t k = 0; k < snapshot.speciesNames.size(); ++k) {
        const int idx = model.species.indexOf(snapshot.speciesNames[k]);
        if (idx < 0)
            throw IoError(snapshotFile + ": species '" + snapshot.speciesNames[k] +
                          "' is not defined in constant/dpdProperties");
        map[k] = static_cast<std::uint8_t>(idx);
    }
    System sys;
    sys.box = snapshot.box;
    sys.particles = std::move(snapshot.particles);
    for (auto& s : sys.particles.species) s = map[s];
    sys.species = model.species;
    sys.pairs = model.pairs;
    sys.forceParameters = {model.cutoff, model.weightExponent, model.kT, dt};
    sys.seed = model.seed;
    sys.bodyForce = model.bodyForce;
    sys.step = snapshot.step;
    sys.time = snapshot.time;
    for (const PlanarWallSettings* w : model.planes())
        for (int a = 0; a < 3; ++a)
            if (sys.box.isActiveAxis(a) && (w->point[a] < sys.box.lo[a] || w->point[a] > sys.box.hi[a]))
                throw IoError("constant/dpdProperties: wall '" + w->name + "' has its point outside the box of " + snapshotFile);
    for (std::size_t w = 0; w < model.walls.size(); ++w) {
        const std::string why = model.walls[w].unfitFor(sys.box);
        if (!why.empty()) throw IoError("constant/dpdProperties: wall '" + model.walls[w].name() + "' does not fit the box of " + snapshotFile + ": " + why);
    }
    sys.walls = model.walls.builtOn({sys.box, model.caseDir, model.cutoff});  // a geometry's field on this box
    const std::string thin = sys.walls.thinWall(model.planes(), sys.box, model.cutoff);
    if (!thin.empty())
        throw IoError("constant/dpdProperties: the solid behind wall '" + thin + "' is thinner than one cutoff inside the box of " +
                      snapshotFile + " (fluid would interact through the wall across the periodic boundary)");
    requireFewInsideWalls(sys, model, snapshotFile);
    addBonds(sys, model, std::move(snapshot.bonds), snapshotFile);
    sys.ranks = ranks;
    sys.slabPlanes = slabPlanes;
    sys.initialise();
    return sys;
}

}  // namespace dpd
