#include "core/Particles.hpp"

namespace dpd {

namespace {
template <class Array>
void permuteArray(Array& a, const std::vector<std::uint32_t>& order, Array& scratch) {
    scratch.resize(a.size());
    for (std::size_t k = 0; k < order.size(); ++k) scratch[k] = a[order[k]];
    a.swap(scratch);
}
}  // namespace

void Particles::resize(std::size_t n) {
    for (auto* a : {&rx, &ry, &rz, &vx, &vy, &vz, &fx, &fy, &fz}) a->resize(n, 0.0);
    id.resize(n, 0);
    species.resize(n, 0);
}

void Particles::reserve(std::size_t n) {
    for (auto* a : {&rx, &ry, &rz, &vx, &vy, &vz, &fx, &fy, &fz}) a->reserve(n);
    id.reserve(n);
    species.reserve(n);
}

void Particles::add(std::uint64_t particleId, int speciesIndex, double x, double y, double z,
                    double ux, double uy, double uz) {
    rx.push_back(x); ry.push_back(y); rz.push_back(z);
    vx.push_back(ux); vy.push_back(uy); vz.push_back(uz);
    fx.push_back(0.0); fy.push_back(0.0); fz.push_back(0.0);
    id.push_back(particleId);
    species.push_back(static_cast<std::uint8_t>(speciesIndex));
}

void Particles::append(const Particles& q) {
    const auto add = [](auto& to, const auto& from) { to.insert(to.end(), from.begin(), from.end()); };
    add(rx, q.rx); add(ry, q.ry); add(rz, q.rz);
    add(vx, q.vx); add(vy, q.vy); add(vz, q.vz);
    add(fx, q.fx); add(fy, q.fy); add(fz, q.fz);
    add(id, q.id);
    add(species, q.species);
}

void Particles::shorten(std::size_t n, bool keepForces) {
    for (auto* a : {&rx, &ry, &rz, &vx, &vy, &vz}) a->resize(n);
    if (!keepForces)
        for (auto* a : {&fx, &fy, &fz}) a->resize(n);
    id.resize(n);
    species.resize(n);
}

Particles Particles::rotated(std::size_t first) const {
    Particles out;
    const auto take = [first](auto& to, const auto& from) {
        to.reserve(from.size());
        to.insert(to.end(), from.begin() + static_cast<long>(first), from.end());
        to.insert(to.end(), from.begin(), from.begin() + static_cast<long>(first));
    };
    take(out.rx, rx); take(out.ry, ry); take(out.rz, rz);
    take(out.vx, vx); take(out.vy, vy); take(out.vz, vz);
    take(out.fx, fx); take(out.fy, fy); take(out.fz, fz);
    take(out.id, id);
    take(out.species, species);
    return out;
}

void Particles::permute(const std::vector<std::uint32_t>& order) {
    ParticleArray<double> scratch;
    for (auto* a : {&rx, &ry, &rz, &vx, &vy, &vz, &fx, &fy, &fz}) permuteArray(*a, order, scratch);
    ParticleArray<std::uint64_t> idScratch;
    permuteArray(id, order, idScratch);
    ParticleArray<std::uint8_t> speciesScratch;
    permuteArray(species, order, speciesScratch);
}

void Particles::clearForces() {
    for (auto* a : {&fx, &fy, &fz}) std::fill(a->begin(), a->end(), 0.0);
}

}  // namespace dpd
