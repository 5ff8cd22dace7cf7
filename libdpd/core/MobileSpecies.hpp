#pragma once
// Which species move, in a form loops over the particles vectorise: one bit per species in a word, so
// that a particle's mobile factor (1 mobile, 0 frozen) is (bits >> species) & 1, a shift vector units
// do for eight particles at once, where a lookup in a byte table is not. Loops scale what they add by
// the factor instead of guarding their stores with a branch, whose only vector form (masked stores)
// costs Zen 3 many times plain stores: measured, the integrator's kick-and-drift pass of a channel
// ran 2.4 times as long with the branch.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace dpd {

// The bits of the species not marked frozen, or nothing where species indices do not fit in a word
// (more than 32 species): such a loop then looks each particle's species up.
inline std::optional<std::uint32_t> mobileSpeciesBits(const std::vector<std::uint8_t>& frozenOfSpecies) {
    if (frozenOfSpecies.size() > 32) return std::nullopt;
    std::uint32_t bits = 0;
    for (std::size_t s = 0; s < frozenOfSpecies.size(); ++s)
        if (frozenOfSpecies[s] == 0) bits |= 1u << s;
    return bits;
}

// 1 for a particle of a mobile species, 0 for a frozen one.
inline double mobileFactor(std::uint32_t mobileBits, std::uint8_t species) {
    return static_cast<double>((mobileBits >> species) & 1u);
}

}  // namespace dpd
