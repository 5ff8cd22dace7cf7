#include "tools/Runner.hpp"

#include "core/Error.hpp"
#include "integrators/Integrator.hpp"
#include "io/Snapshot.hpp"
#include "io/TimeDirectories.hpp"
#include "io/TimeDirectoryWriter.hpp"
#include "case/ControlDict.hpp"
#include "case/DecomposeParDict.hpp"
#include "case/DpdProperties.hpp"
#include "case/RunCompatibility.hpp"
#include "parallel/Communicator.hpp"
#include "parallel/RankChains.hpp"
#include "system/Monitors.hpp"
#include "system/System.hpp"
#include "core/ThreadBudget.hpp"
#include "sampling/FunctionObjects.hpp"


#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <ostream>
#include <sstream>

namespace dpd {

namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;

std::string startTimeName(const std::string& caseDir, const RunControl& control) {
    const auto times = listTimes(caseDir);
    if (times.empty()) throw IoError(caseDir + ": no time directory to start from (run blockFrozenWall first?)");
    if (control.startFrom == "latestTime") return times.back().name;
    for (const auto& t : times)
        if (std::abs(t.value - control.startTime) <= 1e-9 * std::max(1.0, control.startTime)) return t.name;
    throw IoError(caseDir + ": startTime " + timeName(control.startTime) + " has no time directory");
}

bool forcesStored(const Particles& p) {
    for (std::size_t i = 0; i < p.size(); ++i)
        if (p.fx[i] != 0.0 || p.fy[i] != 0.0 || p.fz[i] != 0.0) return true;
    return false;
}

// Whether the snapshot held forces (on any rank's part of it).
bool forcesStored(const System& sys) {
    const bool here = forcesStored(sys.particles);
    return sys.domain() ? !sys.domain()->communicator().all(!here) : here;
}

// A stream that writes nothing: the log of a rank other than the first.
class NullBuffer : public std::streambuf {
protected:
    int overflow(int c) override { return c; }
};

std::string vectorText(const Eigen::Vector3d& v) {
    std::ostringstream os;
    os << std::setprecision(6) << "(" << v.x() << " " << v.y() << " " << v.z() << ")";
    return os.str();
}

std::string clockText(double seconds) {
    const long s = static_cast<long>(std::max(0.0, seconds));
    std::ostringstream os;
    os << std::setfill('0') << std::setw(2) << s / 3600 << ":" << std::setw(2) << (s / 60) % 60 << ":" << std::setw(2)
       << s % 60;
    return os.str();
}

// The state as a snapshot; in a decomposed run this rank's particles only (see wholeSnapshot).
Snapshot snapshotOf(const System& sys) {
    Snapshot s;
    s.box = sys.box;
    s.particles = sys.orderedParticles();
    s.speciesNames = sys.species.names();
    for (int k = 0; k < sys.species.size(); ++k) s.speciesFrozen.push_back(sys.species[k].frozen);
    s.time = sys.time;
    s.step = sys.step;
    s.bonds = sys.bonds.bonds();
    return s;
}

// What to write of a snapshot: on one rank the snapshot itself; in a decomposed run every rank's part
// gathered on the first rank (into `gathered`), in the order of one rank's run (the file a single rank
// would write).
const Snapshot& wholeSnapshot(const System& sys, const Snapshot& part, Snapshot& gathered) {
    if (!sys.domain()) return part;
    gathered = part;
    gathered.particles = sys.domain()->gather(part.particles);
    if (!part.bonds.empty()) gathered.bonds = bondsOnRoot(sys.domain()->communicator(), part.bonds, part.particles);
    return gathered;
}

// What the walls did on every rank together (their counts on one rank).
WallCounters countsOfEveryRank(const System& sys, WallCounters c) {
    if (!sys.domain()) return c;
    const Communicator& comm = sys.domain()->communicator();
    c.returned.resize(sys.walls.size(), 0);
    c.crossed.resize(sys.walls.size(), 0);
    comm.sum(c.returned.data(), c.returned.size());
    comm.sum(c.crossed.data(), c.crossed.size());
    c.insideAfter = comm.sum(c.insideAfter);
    return c;
}

void printWalls(std::ostream& log, const System& sys) {
    for (std::size_t w = 0; w < sys.walls.size(); ++w) {
        const Wall& wall = sys.walls[w];
        log << "    " << wall.name() << ": " << wall.description();
        if (wall.carriesFrozenParticles()) log << ", " << sys.frozenPerWall()[w] << " frozen particles moving with it";
        log << "\n";
    }
}

// "2 of 2" on one process; under MPI "2 of 2 on every rank", or the range "1-2 of 2 per rank" when the
// ranks' budgets differ (a test reads this line to know every rank ran the threads it asked for).
std::string threadsText(const System& sys, const ThreadUse& threads) {
    const std::string ofAvailable = " of " + std::to_string(threads.available);
    if (!sys.domain()) return std::to_string(threads.used) + ofAvailable;
    const Communicator& comm = sys.domain()->communicator();
    const int most = static_cast<int>(comm.max(static_cast<double>(threads.used)));
    const int fewest = -static_cast<int>(comm.max(-static_cast<double>(threads.used)));
    if (fewest == most) return std::to_string(most) + ofAvailable + " on every rank";
    return std::to_string(fewest) + "-" + std::to_string(most) + ofAvailable + " per rank";
}

void printHeader(std::ostream& log, const std::string& caseDir, const System& sys, const ThreadUse& threads,
                 const Integrator& integrator,
                 const RunControl& control, std::size_t nFunctions, const DpdModel& model) {
    const std::size_t mobile = static_cast<std::size_t>(sys.sumOverRanks(static_cast<long>(sys.countMobile())));
    const std::size_t particles = static_cast<std::size_t>(sys.sumOverRanks(static_cast<long>(sys.particles.size())));
    log << "Case           : " << caseDir << "\n";
    if (sys.domain())
        log << "Ranks          : " << sys.domain()->communicator().size() << ", slabs of cell planes along x "
            << sys.domain()->slabs().describe() << " (of " << sys.domain()->slabs().planes() << ")\n";
    log << "Threads        : " << threadsText(sys, threads)
        << (threads.used < threads.available ? " (fewer particles than " + std::to_string(threads.perThread) +
                                                   " per thread: more would wait on each other)"
                                             : std::string())
        << "\n"
        << "Dimension      : " << sys.box.dimension << "\n"
        << "Particles      : " << particles << " (" << mobile << " mobile, " << particles - mobile << " frozen)\n"
        << "Integrator     : " << integrator.name() << ", deltaT " << control.deltaT << "\n"
        << "Pair force     : dissipative + random" << (sys.usesConservativeForce() ? " + conservative" : "")
        << (sys.forceParameters.weightExponent == 2.0 ? "" : ", generalised weight") << "\n"
        << "Walls          : " << sys.walls.size() << "\n";
    printWalls(log, sys);
    for (const std::string& note : model.wallNotes) log << "Slip length    : " << note << "\n";
    for (const std::string& note : model.pairNotes) log << "Pair mixed     : " << note << "\n";
    for (const std::string& note : model.inputNotes) log << "Note           : " << note << "\n";
    if (!sys.bonds.empty())
        log << "Bonds          : " << sys.bonds.size() << " in " << sys.bonds.chainCount() << " chains, "
            << sys.bondPotential->description() << "; " << sys.bondedPairs.description() << "\n";
    log << "Body force     : " << (sys.bodyForce->active() ? vectorText(sys.bodyForce->value()) : std::string("none")) << "\n"
        << "Sampling       : " << nFunctions << " function object(s)\n\n";
}

class RunLoop {
public:
    RunLoop(const std::string& caseDir, std::ostream& log) : caseDir_(caseDir), log_(log) {}

    void run() {
        // Everything is read and checked before anything is written.
        const RunControl control = readControlDict(caseDir_);
        removeUnfinishedTimeDirectories(caseDir_);
        const DpdModel model = readDpdProperties(caseDir_);
        const std::string start = startTimeName(caseDir_, control);
        const std::string snapshotFile = (fs::path(caseDir_) / start / "particles.h5").string();
        const Communicator& world = Communicator::world();
        const DecomposeSettings decomposition = readDecomposeParDict(caseDir_, world.size());
        Snapshot snapshot = readSnapshot(snapshotFile);
        checkPlanesFitBox(decomposition, snapshot.box, model.cutoff,
                          ghostReachFor(model.cutoff, snapshot.bonds.empty() ? nullptr : model.bondPotential.get()));
        System sys = buildSystem(model, std::move(snapshot), control.deltaT, snapshotFile, &world, decomposition.planes);
        FunctionObjects functions = FunctionObjects::read(control.functions, sys);
        checkCompatibility(runParts(model, sys.domain() ? world.size() : 1, functions, control));
        const auto integrator = makeIntegrator(model.integrator);
        if (sys.time > 0.0) functions.restore((fs::path(caseDir_) / start).string());
        // Each rank adds its own samples; what the time directory held counts once.
        if (sys.domain()) functions.keepRestoredSums(Communicator::world().isRoot());
        const ThreadUse threads = useThreadsForParticles(sys.particles.size());
        const bool restartForces = forcesStored(sys);
        sys.sortByCell();
        if (!restartForces) sys.computeForces();
        sys.dropGhosts();
        mobileParticles_ = static_cast<double>(sys.sumOverRanks(static_cast<long>(sys.countMobile())));
        printHeader(log_, caseDir_, sys, threads, *integrator, control, functions.size(), model);
        log_.flush();  // the set-up shows in a log file at once, not with the first report
        loop(sys, control, model, functions, *integrator);
    }

private:
    // Everything the run is made of, for the check pass before anything runs.
    static std::vector<RunPart> runParts(const DpdModel& model, int ranks, const FunctionObjects& functions,
                                         const RunControl& control) {
        std::vector<RunPart> parts = caseParts(model);
        parts.push_back(ranksPart(ranks));
        for (RunPart& f : functionParts(functions, control.functions)) parts.push_back(std::move(f));
        return parts;
    }

    void loop(System& sys, const RunControl& control, const DpdModel& model, FunctionObjects& functions,
              Integrator& integrator) {
        const FlowAxes flowAxes = flowAxesOf(sys);
        const double stepsLeft = (control.endTime - sys.time) / control.deltaT;
        if (stepsLeft < -0.5)
            throw IoError(control.file + ": endTime " + timeName(control.endTime) + " is before the time the run starts from, " +
                          timeName(sys.time));
        if (!(stepsLeft <= 9007199254740992.0))
            throw IoError(control.file + ": endTime " + timeName(control.endTime) + " is more than 2^53 steps after " +
                          timeName(sys.time));
        const auto nSteps = static_cast<std::int64_t>(std::llround(stepsLeft));
        const std::int64_t firstStep = sys.step;
        lastGood_ = snapshotOf(sys);
        WallCounters interval;
        const auto t0 = Clock::now();
        auto tReport = t0;
        std::int64_t stepsAtReport = 0;
        for (std::int64_t k = 1; k <= nSteps; ++k) {
            interval.accumulate(integrator.step(sys));
            if (!sys.bondPass().ok()) stopOnBrokenBond(sys);
            functions.execute(sys);
            const bool report = k % control.reportIntervalSteps == 0 || k == nSteps;
            const bool writeNow = (sys.step - firstStep) % control.writeIntervalSteps == 0 || k == nSteps;
            // Health is checked at every report, before every write (nothing unhealthy is written) and
            // at least every checkInterval steps (a runaway stops soon, whatever the report interval).
            if (!report && !writeNow && k % model.stability.checkIntervalSteps != 0) continue;
            const MonitorReport m = monitor(sys, flowAxes);
            if (report) {
                const auto now = Clock::now();
                const double elapsed = std::chrono::duration<double>(now - t0).count();
                const double rate = (k - stepsAtReport) / std::chrono::duration<double>(now - tReport).count();
                tReport = now;
                stepsAtReport = k;
                printReport(sys, m, countsOfEveryRank(sys, interval), elapsed, rate, nSteps - k);
                interval = WallCounters();
            }
            checkStability(sys, m, model);
            lastGood_ = snapshotOf(sys);
            if (writeNow) write(functions, sys);
        }
        const double total = std::chrono::duration<double>(Clock::now() - t0).count();
        log_ << "\nRun finished: " << nSteps << " steps in " << std::setprecision(4) << total << " s, "
             << std::setprecision(4) << (total > 0 ? mobileParticles_ * nSteps / total : 0.0)
             << " particle-steps/s\nEnd\n";
    }

    void printReport(const System& sys, const MonitorReport& m, const WallCounters& walls, double elapsed,
                     double stepsPerSecond, std::int64_t stepsLeft) {
        log_ << "Time = " << timeName(sys.time) << "  (step " << sys.step << ")\n"
             << "    kT = " << std::setprecision(6) << m.kT << "   momentum = " << vectorText(m.momentum)
             << "   meanVelocity = " << vectorText(m.meanVelocity) << "\n";
        if (!sys.walls.empty()) {
            // Since the last report: particles each wall's rule returned, and particles found in its
            // solid after a move (for a bounce layer each of these is a failure of the layer).
            log_ << "    walls since last report:";
            for (std::size_t w = 0; w < sys.walls.size(); ++w)
                log_ << " " << sys.walls[w].name() << " returned " << (w < walls.returned.size() ? walls.returned[w] : 0)
                     << " crossed " << (w < walls.crossed.size() ? walls.crossed[w] : 0) << ";";
            log_ << " left inside after a step " << walls.insideAfter << "; inside walls now " << m.insideWalls << "\n";
        }
        if (!sys.bonds.empty())  // how near the springs are to their limit (the last step's longest bond)
            log_ << "    bonds: longest " << std::setprecision(4) << std::sqrt(sys.bondPass().longest2) << " of rMax "
                 << sys.bondPotential->maxLength() << "\n";
        log_ << "    ExecutionTime = " << std::setprecision(5) << elapsed << " s   steps/s = " << std::setprecision(4)
             << stepsPerSecond << "   particle-steps/s = " << std::setprecision(4)
             << stepsPerSecond * mobileParticles_ << "   time left = " << clockText(stepsLeft / stepsPerSecond)
             << "\n\n";
        log_.flush();
    }

    void checkStability(const System& sys, const MonitorReport& m, const DpdModel& model) {
        std::string problem;
        if (!m.finite) problem = "non-finite positions, velocities or forces (NaN or infinity)";
        else if (m.kT > model.stability.maxKTRatio * model.kT)
            problem = "kT = " + std::to_string(m.kT) + " exceeds maxKTRatio x kT = " +
                      std::to_string(model.stability.maxKTRatio * model.kT) + " (temperature runaway: is deltaT too large?)";
        else if (m.insideWalls > model.stability.maxInsideWalls)
            problem = std::to_string(m.insideWalls) + " particles found inside walls (allowed: " +
                      std::to_string(model.stability.maxInsideWalls) + ")";
        if (problem.empty()) return;
        stopUnstable(sys, problem);
    }

    // Keeps the last good state (written unless it already is) and stops the run.
    [[noreturn]] void stopUnstable(const System& sys, const std::string& problem) {
        const std::string dir = (fs::path(caseDir_) / timeName(lastGood_.time)).string();
        // Only the particles: the sampling of that time, if it was written, stays as it was.
        Snapshot gathered;
        const Snapshot& whole = wholeSnapshot(sys, lastGood_, gathered);
        if (Communicator::world().isRoot() && !fs::exists(fs::path(dir) / "particles.h5"))
            writeTimeDirectory(caseDir_, timeName(lastGood_.time), [&](const std::string& d) { writeSnapshot(d, whole); });
        throw InstabilityError("the run went unstable at time " + timeName(sys.time) + " (step " +
                               std::to_string(sys.step) + "): " + problem + ". The last good state, time " +
                               timeName(lastGood_.time) + ", is written to " + dir);
    }

    // A bond at or beyond the spring's length has no force and cannot be followed: stop at once.
    void stopOnBrokenBond(const System& sys) {
        const BondPassResult& pass = sys.bondPass();
        const Bonds& b = sys.bonds.bonds();
        const auto k = static_cast<std::size_t>(pass.broken);
        std::ostringstream problem;
        problem << "the bond between particles " << b.first[k] << " and " << b.second[k] << " (chain " << b.chain[k] << ") is ";
        if (pass.brokenLength == kUnseenBondLength)  // a decomposed run's ranks each held one of the two
            problem << "longer than the ghost planes reach (" << sys.ghostReach() << " or more along x)";
        else
            problem << pass.brokenLength << " long";
        problem << ", not shorter than the spring's maximum " << sys.bondPotential->maxLength()
                << " (overstretched: is deltaT too large or the flow too strong?)";
        stopUnstable(sys, problem.str());
    }

    // Writes the state just checked (lastGood_) and the function objects' data, as one directory.
    void write(const FunctionObjects& functions, const System& sys) {
        Snapshot gathered;
        const Snapshot& whole = wholeSnapshot(sys, lastGood_, gathered);
        const FunctionObjects summed = sys.domain() ? functions.summedOverRanks(sys.domain()->communicator()) : FunctionObjects();
        if (Communicator::world().isRoot())
            writeTimeDirectory(caseDir_, timeName(lastGood_.time), [&](const std::string& dir) {
                writeSnapshot(dir, whole);
                (sys.domain() ? summed : functions).write(dir, sys);
            });
        log_ << "Writing time " << timeName(lastGood_.time) << "\n";
    }

    std::string caseDir_;
    std::ostream& log_;
    Snapshot lastGood_;
    // On every rank together. The rates count the particles that move, as dpdBenchmark does: frozen wall
    // particles are held besides (the header's Particles line says how many).
    double mobileParticles_ = 0.0;
};

}  // namespace

void runCase(const std::string& caseDir, std::ostream& log) {
    // The first rank writes the log; the others run silently beside it.
    NullBuffer nothing;
    std::ostream silent(&nothing);
    RunLoop(caseDir, Communicator::world().isRoot() ? log : silent).run();
}

}  // namespace dpd
