#include "parallel/ParticleColumns.hpp"

#include <cstring>

namespace dpd {

namespace {

constexpr std::size_t roundUpTo8(std::size_t n) { return (n + 7) / 8 * 8; }

// One field of every listed particle, at `to`; returns the end (padded to eight bytes). Runs of
// consecutive particles of the same arrays (most of a plane: they lie in cell order) are copied whole.
template <class T, class Field>
char* writeColumn(const ParticleRefs& list, char* to, Field field) {
    std::size_t k = 0;
    while (k < list.size()) {
        const auto [q, first] = list[k];
        std::size_t run = 1;
        while (k + run < list.size() && list[k + run].first == q && list[k + run].second == first + run) ++run;
        std::memcpy(to + k * sizeof(T), field(*q).data() + first, run * sizeof(T));
        k += run;
    }
    const std::size_t bytes = list.size() * sizeof(T), padded = roundUpTo8(bytes);
    std::memset(to + bytes, 0, padded - bytes);  // every byte sent is defined
    return to + padded;
}

// Appends `count` values of one field read at `from`; returns the end (padded to eight bytes).
template <class Array>
const char* appendColumn(const char* from, std::size_t count, Array& a) {
    const std::size_t at = a.size();
    a.resize(at + count);
    const std::size_t bytes = count * sizeof(typename Array::value_type);
    std::memcpy(a.data() + at, from, bytes);
    return from + roundUpTo8(bytes);
}

}  // namespace

std::size_t columnBytes(std::size_t count) {
    return sizeof(std::uint64_t) + count * (9 * sizeof(double) + sizeof(std::uint64_t)) + roundUpTo8(count);
}

char* writeColumns(const ParticleRefs& list, char* to) {
    const std::uint64_t count = list.size();
    std::memcpy(to, &count, sizeof count);
    to += sizeof count;
    using Doubles = ParticleArray<double> Particles::*;
    for (const Doubles field : {&Particles::rx, &Particles::ry, &Particles::rz, &Particles::vx, &Particles::vy,
                                &Particles::vz, &Particles::fx, &Particles::fy, &Particles::fz})
        to = writeColumn<double>(list, to, [field](const Particles& q) -> const ParticleArray<double>& { return q.*field; });
    to = writeColumn<std::uint64_t>(list, to, [](const Particles& q) -> const ParticleArray<std::uint64_t>& { return q.id; });
    return writeColumn<std::uint8_t>(list, to, [](const Particles& q) -> const ParticleArray<std::uint8_t>& { return q.species; });
}

const char* appendColumns(const char* from, Particles& p) {
    std::uint64_t count = 0;
    std::memcpy(&count, from, sizeof count);
    from += sizeof count;
    for (auto* a : {&p.rx, &p.ry, &p.rz, &p.vx, &p.vy, &p.vz, &p.fx, &p.fy, &p.fz}) from = appendColumn(from, count, *a);
    from = appendColumn(from, count, p.id);
    return appendColumn(from, count, p.species);
}

}  // namespace dpd
