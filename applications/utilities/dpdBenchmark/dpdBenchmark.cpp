// dpdBenchmark: how fast. Particle-steps per second of the standard DPD fluid (rho 3, a 25, gamma 4.5,
// kT 1, dt 0.04, Groot-Warren lambda 0.65) and of a channel between frozen walls, at chosen particle
// counts and thread counts, with the time per step split by phase and the memory per particle. Prints
// a table and, with -output, writes it to a file (whole or not at all). in.dpd.lammps beside this file
// runs the same fluid in LAMMPS; README.md says how to compare.
#include "BenchmarkTiming.hpp"

#include "app/ToolCommandLine.hpp"
#include "io/AtomicFile.hpp"
#include "parallel/Communicator.hpp"
#include "parallel/MpiSession.hpp"
#include "parallel/PingPong.hpp"

#include <boost/program_options.hpp>

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace po = boost::program_options;

namespace {

template <class T>
std::vector<T> parseList(const std::string& text, const std::string& option) {
    std::vector<T> values;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) {
        std::istringstream field(item);
        double v = 0.0;
        if (!(field >> v) || !(field >> std::ws).eof() || v <= 0.0)
            throw std::invalid_argument("-" + option + ": '" + item + "' is not a positive number");
        values.push_back(static_cast<T>(v));
    }
    if (values.empty()) throw std::invalid_argument("-" + option + " needs at least one value");
    return values;
}

std::vector<std::string> parseScenes(const std::string& text) {
    std::vector<std::string> scenes;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ','))
        if (item == "fluid" || item == "channel" || item == "chains" || item == "geometry") scenes.push_back(item);
        else throw std::invalid_argument("-scenes: unknown scene '" + item + "' (expected fluid, chains, channel or geometry)");
    return scenes;
}

// How idle OpenMP threads wait at barriers changes the two-thread rates by ~10 % on a shared machine
// (passive: they sleep, and each barrier pays a wake-up), so the table says which policy it ran under.
std::string waitPolicyLine() {
    const char* policy = std::getenv("OMP_WAIT_POLICY");
    return std::string("# OMP_WAIT_POLICY: ") +
           (policy && *policy ? policy : "unset (libgomp's default: spin a while at a barrier, then sleep)") + "\n";
}

std::string tableHeader() {
    return "# dpdBenchmark: particle-steps/s (best of the timed segments), fractions of the step by phase, bytes\n"
           "# per particle. particles: the mobile ones, which the rates count; frozen: wall or grain particles held\n"
           "# besides. rate: wall clock; cpuRate: per CPU second x threads; spread: worst/best segment - 1;\n"
           "# steal: share of the best segment's CPU time the hypervisor gave to other guests (shared machine).\n" +
           waitPolicyLine() +
           "# scene    particles  frozen threads ranks  rate       cpuRate    spread  steal   ms/step   pairs neighb  exch  walls  integ  sampl  bytes/p  kT\n";
}

std::string tableRow(const dpd::BenchmarkResult& r) {
    char line[256];
    std::snprintf(line, sizeof line,
                  "%-9s %9zu %7zu %7d %5d  %9.3e  %9.3e  %6.3f  %6.3f  %8.3f  %5.3f  %5.3f  %5.3f  %5.3f  %5.3f  %5.3f  %7.1f  %.3f\n",
                  r.scene.c_str(), r.particles, r.frozen, r.threads, r.ranks, r.rate, r.cpuRate, r.spread, r.steal, r.msPerStep,
                  r.pairs, r.neighbours, r.exchange, r.walls, r.integration, r.sampling, r.bytesPerParticle, r.kT);
    return line;
}

// One-way time of messages from 8 bytes to 2 MiB between ranks 0 and 1, with the latency (the
// smallest message's time) and the bandwidth (the largest message's size over its time).
std::string pingPongTable(const dpd::Communicator& comm) {
    std::string table = "# dpdBenchmark -pingpong: one-way time of a message between two ranks (half the round trip)\n"
                         "# bytes      seconds     MB/s\n";
    for (std::size_t bytes = 8; bytes <= (std::size_t(2) << 20); bytes *= 8) {
        const int repeats = bytes < 65536 ? 2000 : 100;
        dpd::oneWaySeconds(comm, bytes, repeats / 10);  // warm up the path
        const double t = dpd::oneWaySeconds(comm, bytes, repeats);
        char line[128];
        std::snprintf(line, sizeof line, "%9zu  %10.3e  %8.1f\n", bytes, t, bytes / t / 1e6);
        table += line;
    }
    return table;
}

}  // namespace

int main(int argc, char** argv) {
    const dpd::MpiSession mpi(argc, argv);
    const dpd::Communicator& world = dpd::Communicator::world();
    const int status = dpd::runTool("dpdBenchmark", [&] {
        po::options_description opts("dpdBenchmark: throughput of the standard DPD fluid and of a walled channel\nOptions");
        std::string particles, threads, scenes, output;
        dpd::BenchmarkSettings settings;
        double a = 25.0;
        int dimension = 3;
        opts.add_options()("help,h", "print this help")
            ("particles,n", po::value<std::string>(&particles)->default_value("32000,256000"),
             "particle counts, comma-separated (e.g. 32000,256000,1000000); per rank under mpirun")
            ("threads", po::value<std::string>(&threads)->default_value("1,2"), "OpenMP thread counts, comma-separated")
            ("scenes", po::value<std::string>(&scenes)->default_value("fluid,channel,geometry"), "fluid, chains (the fluid with 10 % of it in chains of 30), channel and/or geometry (the fluid through grains)")
            ("steps", po::value<int>(&settings.steps)->default_value(100), "steps per timed segment")
            ("segments", po::value<int>(&settings.segments)->default_value(3), "timed segments (the best counts)")
            ("warmup", po::value<int>(&settings.warmup)->default_value(10), "untimed steps first")
            ("a", po::value<double>(&a)->default_value(25.0), "fluid: conservative amplitude (0 switches the term off)")
            ("dimension", po::value<int>(&dimension)->default_value(3), "fluid: 2 or 3")
            ("output", po::value<std::string>(&output), "also write the table to this file")
            ("pingpong", "under mpirun -np 2: the one-way time of messages between the two ranks (latency, bandwidth)");
        po::variables_map vm;
        try {
            const int style = po::command_line_style::default_style | po::command_line_style::allow_long_disguise;
            po::store(po::command_line_parser(argc, argv).options(opts).style(style).run(), vm);
            po::notify(vm);
        } catch (const po::error& e) {
            throw std::invalid_argument(e.what());
        }
        if (vm.count("help")) { if (world.isRoot()) std::cout << opts; return; }
        if (vm.count("pingpong")) {
            const std::string table = pingPongTable(world);
            if (world.isRoot()) {
                std::cout << table;
                if (!output.empty()) dpd::writeTextFileAtomically(output, table, true);
            }
            return;
        }
        if (settings.steps < 1 || settings.segments < 1 || settings.warmup < 0)
            throw std::invalid_argument("-steps and -segments must be at least 1, -warmup at least 0");
        if (dimension != 2 && dimension != 3) throw std::invalid_argument("-dimension must be 2 or 3");
        const auto counts = parseList<std::size_t>(particles, "particles");
        const auto threadCounts = parseList<int>(threads, "threads");
        const auto sceneNames = parseScenes(scenes);
        if (world.parallel())
            for (const std::string& name : sceneNames)
                if (name == "channel" || name == "geometry")
                    throw std::invalid_argument("-scenes: the " + name + " scene does not run on several ranks (fluid and chains do)");

        // The first rank prints; the others time their slabs beside it.
        std::ostream& out = std::cout;
        const bool root = world.isRoot();
        std::string table = tableHeader();
        if (root) out << table << std::flush;
        for (const std::string& name : sceneNames)
            for (std::size_t n : counts) {
                const dpd::BenchmarkScene scene =
                    name == "fluid"    ? dpd::makeFluidScene(n, a, dimension, world)
                    : name == "chains"  ? dpd::makeChainsScene(n, a, world)
                    : name == "channel" ? dpd::makeChannelScene(n)
                                        : dpd::makeGeometryScene(n);
                for (int t : threadCounts) {
                    const std::string row = tableRow(dpd::timeScene(scene, t, settings));
                    if (root) out << row << std::flush;
                    table += row;
                }
            }
        if (root && !output.empty()) dpd::writeTextFileAtomically(output, table, true);
    });
    if (status != 0 && world.parallel()) world.abort(status);
    return status;
}
