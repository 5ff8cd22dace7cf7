#include "studies/SpeedAccuracyStudy.hpp"

#include "io/Dictionary.hpp"
#include "system/System.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <stdexcept>

namespace dpd {

namespace {

StandardFluidSettings readFluid(const Dictionary& d) {
    StandardFluidSettings f;
    if (!d.found("fluid")) return f;
    const Dictionary& fd = d.subDict("fluid");
    fd.checkKeys({"particles", "density", "a", "gamma", "kT", "seed"});
    f.particles = static_cast<std::size_t>(fd.getOrDefault<long>("particles", static_cast<long>(f.particles)));
    f.density = fd.getOrDefault<double>("density", f.density);
    f.a = fd.getOrDefault<double>("a", f.a);
    f.gamma = fd.getOrDefault<double>("gamma", f.gamma);
    f.kT = fd.getOrDefault<double>("kT", f.kT);
    f.seed = static_cast<std::uint64_t>(fd.getOrDefault<long>("seed", static_cast<long>(f.seed)));
    if (f.particles < 100) fd.fail("particles", "at least 100 particles");
    if (!(f.density > 0.0)) fd.fail("density", "must be positive");
    if (!(f.kT > 0.0)) fd.fail("kT", "must be positive");
    return f;
}

std::vector<SpeedAccuracyCase> readIntegrators(const Dictionary& d) {
    const Dictionary& id = d.subDict("integrators");
    std::vector<SpeedAccuracyCase> cases;
    for (const std::string& label : id.keys()) {
        if (!id.isDict(label)) id.fail(label, "each integrator is a sub-dictionary, e.g. GW { type GrootWarren; }");
        cases.push_back({label, IntegratorSettings::read(id.subDict(label))});
    }
    if (cases.empty()) d.fail("integrators", "at least one integrator");
    return cases;
}

// Equilibration, production and blocks of a probe from its dictionary.
void readRunTimes(const Dictionary& d, TemperatureProbeSettings& probe) {
    probe.equilibrationTime = d.getNonNegative<double>("equilibrationTime");
    probe.productionTime = d.getPositive<double>("productionTime");
    const double blockTime = d.getPositive<double>("blockTime");
    probe.blocks = static_cast<int>(std::floor(probe.productionTime / blockTime));
    if (probe.blocks < 2) d.fail("blockTime", "productionTime must hold at least two blocks");
}

void readViscosity(const Dictionary& d, SpeedAccuracySettings& s) {
    s.viscosity = true;
    d.checkKeys({"lengthRatio", "g", "bins", "exclude", "startNu", "equilibrationTime", "productionTime", "blockTime"});
    s.viscosityLengthRatio = d.getPositive<double>("lengthRatio");
    ViscosityProbeSettings& v = s.viscosityProbe;
    v.g = d.getPositive<double>("g");
    v.bins = static_cast<int>(d.getPositive<long>("bins"));
    v.exclude = d.getNonNegative<double>("exclude");
    v.startNu = d.found("startNu") ? d.getPositive<double>("startNu") : 0.0;
    readRunTimes(d, v.run);
    v.run.maxKTRatio = s.probe.maxKTRatio;
    // The fit needs four bins per half of the box clear of the jump layers.
    const double volume = static_cast<double>(s.fluid.particles) / s.fluid.density;
    const double side = s.fluid.dimension == 3 ? std::cbrt(volume) : std::sqrt(volume);
    const double lz = side * s.viscosityLengthRatio;
    const double width = lz / v.bins;
    if (0.5 * lz - 2.0 * v.exclude < 4.0 * width)
        d.fail("bins", "fewer than four bins per half of the box (Lz " + std::to_string(lz) + ") outside the excluded layers");
}

}  // namespace

SpeedAccuracySettings readSpeedAccuracySettings(const Dictionary& d) {
    d.checkKeys({"fluid", "integrators", "deltaT", "reference", "referenceDeltaT", "referenceTimeFactor", "equilibrationTime", "productionTime", "blockTime",
                 "maxKTRatio", "viscosity"});
    SpeedAccuracySettings s;
    s.fluid = readFluid(d);
    s.integrators = readIntegrators(d);
    s.deltaT = d.get<std::vector<double>>("deltaT");
    if (s.deltaT.empty()) d.fail("deltaT", "at least one step");
    for (double dt : s.deltaT)
        if (!(dt > 0.0)) d.fail("deltaT", "every step must be positive");
    s.reference = d.get<std::string>("reference");
    if (std::none_of(s.integrators.begin(), s.integrators.end(), [&](const SpeedAccuracyCase& c) { return c.label == s.reference; }))
        d.fail("reference", "'" + s.reference + "' is not one of the integrators");
    const double smallest = *std::min_element(s.deltaT.begin(), s.deltaT.end());
    s.referenceDeltaT = d.found("referenceDeltaT") ? d.get<double>("referenceDeltaT") : 0.5 * smallest;
    if (!(s.referenceDeltaT > 0.0 && s.referenceDeltaT < smallest))
        d.fail("referenceDeltaT", "the reference step must be positive and smaller than every deltaT (the smallest is " +
                                      std::to_string(smallest) + "): a studied run is not its own reference");
    s.referenceTimeFactor = d.found("referenceTimeFactor") ? d.getPositive<int>("referenceTimeFactor") : 4;
    readRunTimes(d, s.probe);
    s.probe.samplePressure = true;
    s.probe.maxKTRatio = d.getOrDefault<double>("maxKTRatio", s.probe.maxKTRatio);
    if (d.found("viscosity")) readViscosity(d.subDict("viscosity"), s);
    return s;
}

namespace {

// The fluid equilibrated from its random start (whose overlaps heat it) by Groot-Warren at dt 0.01
// for 1000 steps, so that a blow-up is the integrator's, not the start's.
System equilibratedFluid(StandardFluidSettings start) {
    start.dt = 0.01;
    System sys = makeStandardFluid(start);
    auto warmUp = makeIntegrator(IntegratorSettings{});
    for (int k = 0; k < 1000; ++k) warmUp->step(sys);
    return sys;
}

// The box of the viscosity runs: the fluid's cross-section, lengthRatio times as long along z.
StandardFluidSettings viscosityFluid(const SpeedAccuracySettings& s) {
    StandardFluidSettings f = s.fluid;
    const double r = s.viscosityLengthRatio;
    f.particles = static_cast<std::size_t>(std::llround(static_cast<double>(s.fluid.particles) * r));
    f.aspect = Eigen::Vector3d(1.0, 1.0, r);
    return f;
}

}  // namespace

namespace {

// One integrator at one step, from the equilibrated states.
SpeedAccuracyRow runCase(const SpeedAccuracySettings& s, const SpeedAccuracyCase& c, double dt, const System& equilibrated,
                         const System& flowFluid, std::ostream& progress) {
    System sys = equilibrated;
    sys.forceParameters.dt = dt;
    sys.computeForces();
    auto integrator = makeIntegrator(c.integrator);
    SpeedAccuracyRow row;
    row.label = c.label;
    row.dt = dt;
    row.result = probeTemperature(sys, *integrator, s.probe);
    row.secondsPerParticleTimeUnit =
        row.result.cpuSeconds / (static_cast<double>(sys.particles.size()) * s.probe.productionTime);
    progress << std::setw(12) << c.label << "  dt " << std::setw(6) << dt << "  ";
    if (row.result.unstable)
        progress << "unstable after " << row.result.unstableAfter << " time units: " << row.result.problem << "\n";
    else
        progress << "kT error " << std::showpos << std::setprecision(3) << 100.0 * (row.result.kT / s.fluid.kT - 1.0)
                 << std::noshowpos << " % +- " << 100.0 * row.result.standardError / s.fluid.kT << " %, "
                 << row.secondsPerParticleTimeUnit << " CPU s per particle per time unit, P " << row.result.pressure
                 << " +- " << row.result.pressureStandardError << "\n";
    if (s.viscosity && !row.result.unstable) {
        System flow = flowFluid;
        flow.forceParameters.dt = dt;
        auto flowIntegrator = makeIntegrator(c.integrator);
        row.hasViscosity = true;
        row.viscosity = probeViscosity(flow, *flowIntegrator, s.viscosityProbe);
        progress << std::setw(12) << "" << "  viscosity: ";
        if (row.viscosity.unstable) progress << "unstable: " << row.viscosity.problem << "\n";
        else
            progress << "nu " << row.viscosity.nu << " +- " << row.viscosity.nuErr << " (chi2/dof "
                     << row.viscosity.chi2PerDof << ")\n";
    }
    progress.flush();
    return row;
}

}  // namespace

std::vector<SpeedAccuracyRow> runSpeedAccuracyStudy(const SpeedAccuracySettings& s, std::ostream& progress) {
    const System equilibrated = equilibratedFluid(s.fluid);
    const System flowFluid = s.viscosity ? equilibratedFluid(viscosityFluid(s)) : System{};
    std::vector<SpeedAccuracyRow> rows;
    const auto reference = std::find_if(s.integrators.begin(), s.integrators.end(),
                                        [&](const SpeedAccuracyCase& c) { return c.label == s.reference; });
    progress << "reference run (" << s.referenceTimeFactor << " times the sampling):\n";
    SpeedAccuracySettings longer = s;
    for (TemperatureProbeSettings* p : {&longer.probe, &longer.viscosityProbe.run}) {
        p->productionTime *= s.referenceTimeFactor;
        p->blocks *= s.referenceTimeFactor;
    }
    rows.push_back(runCase(longer, *reference, s.referenceDeltaT, equilibrated, flowFluid, progress));
    rows.back().isReference = true;
    progress << "studied steps:\n";
    for (const SpeedAccuracyCase& c : s.integrators)
        for (double dt : s.deltaT) rows.push_back(runCase(s, c, dt, equilibrated, flowFluid, progress));
    return rows;
}

namespace {

struct Estimate {
    double value = std::nan(""), error = std::nan("");
};

Estimate pressureOf(const SpeedAccuracyRow& r) {
    if (r.result.unstable) return {};
    return {r.result.pressure, r.result.pressureStandardError};
}

Estimate viscosityOf(const SpeedAccuracyRow& r) {
    if (r.result.unstable || !r.hasViscosity || r.viscosity.unstable) return {};
    return {r.viscosity.nu, r.viscosity.nuErr};
}

// x / reference - 1 with the two errors in quadrature (the runs are independent).
Estimate relativeError(const Estimate& x, const Estimate& reference) {
    return {x.value / reference.value - 1.0, std::hypot(x.error, reference.error) / reference.value};
}

}  // namespace

std::string speedAccuracyTable(const std::vector<SpeedAccuracyRow>& rows, const SpeedAccuracySettings& s) {
    const SpeedAccuracyRow* reference = nullptr;
    for (const SpeedAccuracyRow& r : rows)
        if (r.isReference) reference = &r;
    const Estimate pRef = reference ? pressureOf(*reference) : Estimate{};
    const Estimate nuRef = reference ? viscosityOf(*reference) : Estimate{};
    std::ostringstream os;
    os << "# integrator dt kTError kTErrorSE pressure pressureSE pressureError pressureErrorSE nu nuSE nuError nuErrorSE "
          "secondsPerParticleTimeUnit unstable unstableAfter\n"
       << "# kTError: <kT> / kT - 1 (relative), kTErrorSE its block standard error; pressure: <P> (virial + kinetic)\n"
       << "# with its block standard error; nu: kinematic viscosity from reverse-Poiseuille flow and its fit error\n"
       << "# (nan: not measured). pressureError, nuError: relative to the reference, " << s.reference << " at dt "
       << (reference ? reference->dt : std::nan("")) << ", their SE both errors in quadrature.\n"
       << "# reference run: " << s.reference << " dt " << (reference ? reference->dt : std::nan("")) << " pressure "
       << pRef.value << " " << pRef.error << " nu " << nuRef.value << " " << nuRef.error << "\n"
       << "# secondsPerParticleTimeUnit: CPU seconds of the process (all threads) per\n"
       << "# particle per time unit simulated, steps only. unstable: 1 when the run's monitor stopped it after\n"
       << "# unstableAfter time units.\n";
    os << std::setprecision(6);
    for (const SpeedAccuracyRow& r : rows) {
        if (r.isReference) continue;
        const bool bad = r.result.unstable;
        const Estimate p = pressureOf(r), nu = viscosityOf(r);
        const Estimate pErr = relativeError(p, pRef), nuErr = relativeError(nu, nuRef);
        const double kT = s.fluid.kT;
        os << r.label << " " << r.dt << " " << (bad ? std::nan("") : r.result.kT / kT - 1.0) << " "
           << (bad ? std::nan("") : r.result.standardError / kT) << " " << p.value << " " << p.error << " " << pErr.value
           << " " << pErr.error << " " << nu.value << " " << nu.error << " " << nuErr.value << " " << nuErr.error << " "
           << (bad ? std::nan("") : r.secondsPerParticleTimeUnit) << " " << (bad ? 1 : 0) << " " << r.result.unstableAfter
           << "\n";
    }
    return os.str();
}

}  // namespace dpd
