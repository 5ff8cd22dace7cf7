#pragma once
// What the pair force needs of the two particles beyond their separation, gathered from the pair
// inputs (PairInputs.hpp) for eight pairs at a time with AVX2: the relative velocity along the
// separation, (r_i - r_j).(v_i - v_j), and the pair's ids ordered (lower first), which key its random
// number. Each particle's velocity and id are one 16-byte entry; the eight entries of the i (or j)
// side are loaded whole and transposed into four vectors of eight lanes. The same numbers to the bit
// as the scalar form below (the dot product summed in the same order with the same fused
// multiply-adds), which the pair loop uses for the last pairs of a batch.
#include "forces/PairInputs.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

#if defined(__AVX2__)
#include <immintrin.h>
#endif

namespace dpd {
namespace detail {

// (r_i - r_j).(v_i - v_j) from the separation d and the velocity difference dv.
inline float separationDotRelativeVelocity(float dx, float dy, float dz, float dvx, float dvy, float dvz) {
    return std::fma(dz, dvz, std::fma(dx, dvx, dy * dvy));
}

struct PairGatherInput {
    const PairKinematics* kinematics;
    const std::uint32_t *i, *j;
    const float *dx, *dy, *dz;
};

struct PairGatherOutput {
    float* rDotV;
    std::uint32_t *idLo, *idHi;
};

#if defined(__AVX2__)
// The entries of particles index[0..7] as four vectors: lane m of vx holds particle index[m]'s vx,
// and so on (the id's bits in the fourth).
struct KinematicsLanes {
    __m256 vx, vy, vz, id;
};

inline KinematicsLanes loadKinematics(const PairKinematics* kin, const std::uint32_t* index) {
    const auto entry = [&](int m) { return _mm_load_ps(&kin[index[m]].vx); };
    // Rows m and m + 4 share a register: the 4 x 4 transposes below work within each 128-bit half.
    const __m256 r0 = _mm256_insertf128_ps(_mm256_castps128_ps256(entry(0)), entry(4), 1);
    const __m256 r1 = _mm256_insertf128_ps(_mm256_castps128_ps256(entry(1)), entry(5), 1);
    const __m256 r2 = _mm256_insertf128_ps(_mm256_castps128_ps256(entry(2)), entry(6), 1);
    const __m256 r3 = _mm256_insertf128_ps(_mm256_castps128_ps256(entry(3)), entry(7), 1);
    const __m256 xy01 = _mm256_unpacklo_ps(r0, r1), zw01 = _mm256_unpackhi_ps(r0, r1);
    const __m256 xy23 = _mm256_unpacklo_ps(r2, r3), zw23 = _mm256_unpackhi_ps(r2, r3);
    return {_mm256_shuffle_ps(xy01, xy23, 0x44), _mm256_shuffle_ps(xy01, xy23, 0xEE),
            _mm256_shuffle_ps(zw01, zw23, 0x44), _mm256_shuffle_ps(zw01, zw23, 0xEE)};
}
#endif

// Fills entries [0, m) of the output, m the largest multiple of eight up to n (0 without AVX2), and
// returns m; the caller finishes the rest with gatherPairKinematicsScalar.
template <bool kVelocity, bool kRandom>
inline std::size_t gatherPairKinematics(const PairGatherInput& in, const PairGatherOutput& out, std::size_t n) {
    std::size_t k = 0;
#if defined(__AVX2__)
    if constexpr (kVelocity || kRandom)
        for (; k + 8 <= n; k += 8) {
            const KinematicsLanes a = loadKinematics(in.kinematics, in.i + k);
            const KinematicsLanes b = loadKinematics(in.kinematics, in.j + k);
            if constexpr (kVelocity) {
                const __m256 dvx = _mm256_sub_ps(a.vx, b.vx);
                const __m256 dvy = _mm256_sub_ps(a.vy, b.vy);
                const __m256 dvz = _mm256_sub_ps(a.vz, b.vz);
                // As separationDotRelativeVelocity, rounding for rounding.
                const __m256 dot = _mm256_fmadd_ps(
                    _mm256_loadu_ps(in.dz + k), dvz,
                    _mm256_fmadd_ps(_mm256_loadu_ps(in.dx + k), dvx, _mm256_mul_ps(_mm256_loadu_ps(in.dy + k), dvy)));
                _mm256_storeu_ps(out.rDotV + k, dot);
            }
            if constexpr (kRandom) {
                const __m256i ia = _mm256_castps_si256(a.id), ib = _mm256_castps_si256(b.id);
                _mm256_storeu_si256(reinterpret_cast<__m256i*>(out.idLo + k), _mm256_min_epu32(ia, ib));
                _mm256_storeu_si256(reinterpret_cast<__m256i*>(out.idHi + k), _mm256_max_epu32(ia, ib));
            }
        }
#else
    (void)in; (void)out; (void)n;
#endif
    return k;
}

// Entries [first, n), one at a time.
template <bool kVelocity, bool kRandom>
inline void gatherPairKinematicsScalar(const PairGatherInput& in, const PairGatherOutput& out, std::size_t first,
                                       std::size_t n) {
    for (std::size_t k = first; k < n; ++k) {
        const PairKinematics& a = in.kinematics[in.i[k]];
        const PairKinematics& b = in.kinematics[in.j[k]];
        if constexpr (kVelocity)
            out.rDotV[k] = separationDotRelativeVelocity(in.dx[k], in.dy[k], in.dz[k], a.vx - b.vx, a.vy - b.vy, a.vz - b.vz);
        if constexpr (kRandom) {
            out.idLo[k] = std::min(a.id, b.id);
            out.idHi[k] = std::max(a.id, b.id);
        }
    }
}

}  // namespace detail
}  // namespace dpd
