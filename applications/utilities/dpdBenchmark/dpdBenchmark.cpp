// dpdBenchmark: particle-steps per second of the standard DPD fluid (rho 3, a 25, gamma 4.5, kT 1,
// dt 0.04, Groot-Warren lambda 0.65) at a chosen particle count and thread count.
#include "integrators/Integrator.hpp"
#include "run/Monitors.hpp"
#include "run/StandardFluid.hpp"

#include <boost/program_options.hpp>
#include <omp.h>

#include <chrono>
#include <cstdio>
#include <iostream>

namespace po = boost::program_options;

int main(int argc, char** argv) {
    po::options_description opts("dpdBenchmark: throughput of the standard DPD fluid\nOptions");
    dpd::StandardFluidSettings fluid;
    int steps = 200, warmup = 20, threads = 0, dimension = 3;
    double a = fluid.a;
    opts.add_options()("help,h", "print this help")
        ("particles,n", po::value<std::size_t>(&fluid.particles)->default_value(32000), "number of particles")
        ("steps", po::value<int>(&steps)->default_value(200), "timed steps")
        ("warmup", po::value<int>(&warmup)->default_value(20), "untimed steps first")
        ("threads", po::value<int>(&threads)->default_value(0), "OpenMP threads (0: OMP_NUM_THREADS or all cores)")
        ("a", po::value<double>(&a)->default_value(25.0), "conservative amplitude (0 switches the term off)")
        ("dimension", po::value<int>(&dimension)->default_value(3), "2 or 3");
    po::variables_map vm;
    try {
        // OpenFOAM-style single-dash long options are accepted too.
        po::store(po::command_line_parser(argc, argv).options(opts).style(po::command_line_style::default_style |
                                                                          po::command_line_style::allow_long_disguise).run(), vm);
        po::notify(vm);
    } catch (const std::exception& e) {
        std::cerr << "dpdBenchmark: " << e.what() << "\n" << opts;
        return 1;
    }
    if (vm.count("help")) { std::cout << opts; return 0; }
    if (threads > 0) omp_set_num_threads(threads);
    fluid.a = a;
    fluid.dimension = dimension;
    dpd::System sys = dpd::makeStandardFluid(fluid);
    auto integrator = dpd::makeIntegrator({"GrootWarren", 0.65});
    for (int s = 0; s < warmup; ++s) integrator->step(sys);
    const auto t0 = std::chrono::steady_clock::now();
    for (int s = 0; s < steps; ++s) integrator->step(sys);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double rate = static_cast<double>(sys.particles.size()) * steps / seconds;
    const dpd::MonitorReport r = dpd::monitor(sys, -1);
    std::printf("particles %zu  threads %d  steps %d  seconds %.3f  particle-steps/s %.4g  kT %.4f\n",
                sys.particles.size(), omp_get_max_threads(), steps, seconds, rate, r.kT);
    return 0;
}
