#include "integrators/SpeedAccuracyStudy.hpp"

#include "io/Dictionary.hpp"
#include "run/System.hpp"

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
        const Dictionary& c = id.subDict(label);
        c.checkKeys({"type", "lambda"});
        SpeedAccuracyCase k{label, {}};
        k.integrator.type = c.get<std::string>("type");
        k.integrator.lambda = c.getOrDefault<double>("lambda", k.integrator.lambda);
        try {
            makeIntegrator(k.integrator);
        } catch (const std::invalid_argument& e) {
            c.fail("type", e.what());
        }
        cases.push_back(k);
    }
    if (cases.empty()) d.fail("integrators", "at least one integrator");
    return cases;
}

}  // namespace

SpeedAccuracySettings readSpeedAccuracySettings(const Dictionary& d) {
    d.checkKeys({"fluid", "integrators", "deltaT", "equilibrationTime", "productionTime", "blockTime", "maxKTRatio"});
    SpeedAccuracySettings s;
    s.fluid = readFluid(d);
    s.integrators = readIntegrators(d);
    s.deltaT = d.get<std::vector<double>>("deltaT");
    if (s.deltaT.empty()) d.fail("deltaT", "at least one step");
    for (double dt : s.deltaT)
        if (!(dt > 0.0)) d.fail("deltaT", "every step must be positive");
    s.probe.equilibrationTime = d.getNonNegative<double>("equilibrationTime");
    s.probe.productionTime = d.getPositive<double>("productionTime");
    const double blockTime = d.getPositive<double>("blockTime");
    s.probe.blocks = static_cast<int>(std::floor(s.probe.productionTime / blockTime));
    if (s.probe.blocks < 2) d.fail("blockTime", "productionTime must hold at least two blocks");
    s.probe.maxKTRatio = d.getOrDefault<double>("maxKTRatio", s.probe.maxKTRatio);
    return s;
}

std::vector<SpeedAccuracyRow> runSpeedAccuracyStudy(const SpeedAccuracySettings& s, std::ostream& progress) {
    StandardFluidSettings start = s.fluid;
    start.dt = 0.01;
    System equilibrated = makeStandardFluid(start);
    auto warmUp = makeIntegrator(IntegratorSettings{});
    for (int k = 0; k < 1000; ++k) warmUp->step(equilibrated);
    std::vector<SpeedAccuracyRow> rows;
    for (const SpeedAccuracyCase& c : s.integrators)
        for (double dt : s.deltaT) {
            System sys = equilibrated;
            sys.forceParameters.dt = dt;
            sys.computeForces();
            auto integrator = makeIntegrator(c.integrator);
            SpeedAccuracyRow row{c.label, dt, probeTemperature(sys, *integrator, s.probe), 0.0};
            row.secondsPerParticleTimeUnit =
                row.result.seconds / (static_cast<double>(sys.particles.size()) * s.probe.productionTime);
            progress << std::setw(12) << c.label << "  dt " << std::setw(6) << dt << "  ";
            if (row.result.unstable)
                progress << "unstable after " << row.result.unstableAfter << " time units: " << row.result.problem << "\n";
            else
                progress << "kT error " << std::showpos << std::setprecision(3) << 100.0 * (row.result.kT / s.fluid.kT - 1.0)
                         << std::noshowpos << " % +- " << 100.0 * row.result.standardError / s.fluid.kT << " %, "
                         << row.secondsPerParticleTimeUnit << " s per particle per time unit\n";
            progress.flush();
            rows.push_back(row);
        }
    return rows;
}

std::string speedAccuracyTable(const std::vector<SpeedAccuracyRow>& rows) {
    std::ostringstream os;
    os << "# integrator dt kTError kTErrorSE secondsPerParticleTimeUnit unstable unstableAfter\n"
       << "# kTError: <kT> / kT - 1 (relative), kTErrorSE its block standard error; unstable: 1 when the\n"
       << "# run's monitor stopped it (kT runaway or NaN) after unstableAfter time units.\n";
    os << std::setprecision(6);
    for (const SpeedAccuracyRow& r : rows) {
        const bool bad = r.result.unstable;
        os << r.label << " " << r.dt << " " << (bad ? std::nan("") : r.result.kT - 1.0) << " "
           << (bad ? std::nan("") : r.result.standardError) << " " << (bad ? std::nan("") : r.secondsPerParticleTimeUnit)
           << " " << (bad ? 1 : 0) << " " << r.result.unstableAfter << "\n";
    }
    return os.str();
}

}  // namespace dpd
