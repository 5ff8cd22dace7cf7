#pragma once
// The particle loop of the integrators' passes: body(i, mobile) for every particle, in parallel.
// Without frozen species `mobile` is the compile-time constant true (std::true_type), so it drops out
// of the loop: the standard fluid pays no per-particle species lookup. With frozen species it is a
// double, 1 for a mobile particle and 0 for a frozen one (core/MobileSpecies.hpp: for species indices
// below 32 a bit of a word, which the loop looks up eight particles at a time). Write the body as a
// generic lambda, [&](long i, auto mobile) { ... }, that reads and writes the entries i of the arrays
// only (the loop is declared `simd`: no iteration depends on another), and let `mobile` scale what it
// adds (mobileFactor(mobile) * h) instead of guarding a store, which would keep the loop from
// vectorising.
#include "core/MobileSpecies.hpp"
#include "system/System.hpp"

#include <algorithm>
#include <cstdint>
#include <type_traits>

namespace dpd {

// 1 for a mobile particle, 0 for a frozen one, for either form of forEachParticle's `mobile`.
inline constexpr double mobileFactor(std::true_type) { return 1.0; }
inline double mobileFactor(double mobile) { return mobile; }

template <class Body>
void forEachParticle(const System& sys, Body body) {
    const std::vector<std::uint8_t>& frozen = sys.frozenOfSpecies();
    const std::uint8_t* species = sys.particles.species.data();
    const long n = static_cast<long>(sys.particles.size());
    if (std::none_of(frozen.begin(), frozen.end(), [](std::uint8_t f) { return f != 0; })) {
#pragma omp parallel for simd schedule(static)
        for (long i = 0; i < n; ++i) body(i, std::true_type{});
    } else if (const std::optional<std::uint32_t> bits = mobileSpeciesBits(frozen)) {
        const std::uint32_t mobileBits = *bits;
#pragma omp parallel for simd schedule(static)
        for (long i = 0; i < n; ++i) body(i, mobileFactor(mobileBits, species[i]));
    } else {
#pragma omp parallel for schedule(static)
        for (long i = 0; i < n; ++i) body(i, frozen[species[i]] == 0 ? 1.0 : 0.0);
    }
}

}  // namespace dpd
