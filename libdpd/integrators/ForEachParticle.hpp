#pragma once
// The particle loop of the integrators' passes: body(i, mobile) for every particle, in parallel.
// Without frozen species `mobile` is the compile-time constant true (std::true_type), so it drops out
// of the loop: the standard fluid pays no per-particle species lookup. With frozen species it is a
// double, 1 for a mobile particle and 0 for a frozen one (for species indices below 32 a bit of a
// word, looked up by a shift that vector units do for eight particles at once). Write the body as a
// generic lambda, [&](long i, auto mobile) { ... }, that reads and writes the entries i of the arrays
// only (the loop is declared `simd`: no iteration depends on another), and let `mobile` scale what it
// adds (mobileFactor(mobile) * h) instead of guarding a store: a branch around a store keeps the loop
// from vectorising (its vector form would be masked stores, which cost Zen 3 many times plain ones).
#include "run/System.hpp"

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
    } else if (frozen.size() <= 32) {
        std::uint32_t mobileBits = 0;
        for (std::size_t s = 0; s < frozen.size(); ++s)
            if (frozen[s] == 0) mobileBits |= 1u << s;
#pragma omp parallel for simd schedule(static)
        for (long i = 0; i < n; ++i) body(i, static_cast<double>((mobileBits >> species[i]) & 1u));
    } else {
#pragma omp parallel for schedule(static)
        for (long i = 0; i < n; ++i) body(i, frozen[species[i]] == 0 ? 1.0 : 0.0);
    }
}

}  // namespace dpd
