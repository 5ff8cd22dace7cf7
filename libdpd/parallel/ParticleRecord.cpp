#include "parallel/ParticleRecord.hpp"

#include <cstring>

namespace dpd {

void writeRecord(const Particles& p, std::size_t i, char* to) {
    ParticleRecord rec{};  // padding zeroed: the bytes sent are all defined
    rec.r[0] = p.rx[i]; rec.r[1] = p.ry[i]; rec.r[2] = p.rz[i];
    rec.v[0] = p.vx[i]; rec.v[1] = p.vy[i]; rec.v[2] = p.vz[i];
    rec.f[0] = p.fx[i]; rec.f[1] = p.fy[i]; rec.f[2] = p.fz[i];
    rec.id = p.id[i];
    rec.species = p.species[i];
    std::memcpy(to, &rec, sizeof rec);
}

void appendRecord(const Particles& p, std::size_t i, std::vector<char>& bytes) {
    const std::size_t at = bytes.size();
    bytes.resize(at + sizeof(ParticleRecord));
    writeRecord(p, i, bytes.data() + at);
}

void appendRecords(const char* from, std::size_t count, Particles& p) {
    const std::size_t at = p.size();
    p.resize(at + count);
    for (std::size_t k = 0; k < count; ++k) {
        ParticleRecord rec;
        std::memcpy(&rec, from + k * sizeof rec, sizeof rec);
        const std::size_t i = at + k;
        p.rx[i] = rec.r[0]; p.ry[i] = rec.r[1]; p.rz[i] = rec.r[2];
        p.vx[i] = rec.v[0]; p.vy[i] = rec.v[1]; p.vz[i] = rec.v[2];
        p.fx[i] = rec.f[0]; p.fy[i] = rec.f[1]; p.fz[i] = rec.f[2];
        p.id[i] = rec.id;
        p.species[i] = rec.species;
    }
}

}  // namespace dpd
