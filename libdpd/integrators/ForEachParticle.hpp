#pragma once
// The particle loop of the integrators' passes: body(i, mobile) for every particle, in parallel, with
// `mobile` false for a frozen one. Without frozen species `mobile` is the compile-time constant true
// (std::true_type), so `if (mobile)` drops out of the loop, which the compiler then vectorises: the
// standard fluid pays no per-particle species lookup. Write the body as a generic lambda,
// [&](long i, auto mobile) { ... }, that reads and writes the entries i of the arrays only (the loop
// is declared `simd`: no iteration depends on another).
#include "run/System.hpp"

#include <algorithm>
#include <cstdint>
#include <type_traits>

namespace dpd {

template <class Body>
void forEachParticle(const System& sys, Body body) {
    const std::vector<std::uint8_t>& frozen = sys.frozenOfSpecies();
    const std::uint8_t* species = sys.particles.species.data();
    const long n = static_cast<long>(sys.particles.size());
    if (std::none_of(frozen.begin(), frozen.end(), [](std::uint8_t f) { return f != 0; })) {
#pragma omp parallel for simd schedule(static)
        for (long i = 0; i < n; ++i) body(i, std::true_type{});
    } else {
#pragma omp parallel for schedule(static)
        for (long i = 0; i < n; ++i) body(i, frozen[species[i]] == 0);
    }
}

}  // namespace dpd
