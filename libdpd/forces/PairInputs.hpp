#pragma once
// What the pair search reads, in single precision and in the cell list's order: each particle's
// position relative to the lower corner of its cell, and, when the force needs them, its velocity and
// its id cut to 32 bits (PairRandom keys pair numbers by the low 32 bits of the ids).
//
// Why single precision: the search tests ~40 candidates per particle at rho 3 for ~6 pairs, and eight
// floats per AVX2 instruction halve its cost against four doubles; the velocities and ids come in
// eight-lane gathers for the same reason. Why cell-local: a position within its cell is smaller than
// a cell, so a float holds it to ~6e-8 (an absolute position in a box 160 long would keep only
// ~1e-5), and periodic images need no shift: a neighbour cell's particles stand at their local
// position plus the stencil offset times the cell size, across the box boundary or not. A pair's
// separation is then good to ~2e-7 of a cutoff, and its (r_i - r_j).(v_i - v_j) to ~1e-7 relative:
// errors far below those of the integrator's step, applied equally (with opposite signs) to both
// particles, so momentum stays exactly conserved.
#include "core/Particles.hpp"
#include "neighbour/CellList.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace dpd {

// A particle's velocity and id side by side, 16 bytes: the pair gather fetches both for a particle
// with one aligned load, and transposes eight such loads into lanes (PairGather.hpp); eight-lane
// gather instructions, one per component, took twice as long (2 against 4 ns per pair).
struct alignas(16) PairKinematics {
    float vx, vy, vz;
    std::uint32_t id;  // low 32 bits of the id
};

// Entries of x, y, z past the last particle: the search loads eight lanes from any particle on,
// unmasked (AVX2's masked loads cost Zen 3 several times a plain one), and ignores what lies past the
// end of a cell.
inline constexpr std::size_t kPairInputPadding = 7;

struct PairInputs {
    ParticleArray<float> x, y, z;           // r - (lower corner of the particle's cell), then the padding
    ParticleArray<PairKinematics> kinematics;  // velocities and ids, each filled only when asked for
    float cellX = 1.0f, cellY = 1.0f, cellZ = 1.0f;  // the cell size

    std::size_t capacityBytes() const;
};

// Fills `in` from particles sorted by `cells` (positions always; velocities and ids when asked).
void fillPairInputs(const Particles& p, const CellList& cells, bool velocities, bool ids, PairInputs& in);

// The velocities of `in` as v + shift f (shift 0 for the particles of species marked frozen, when
// frozenOfSpecies is not null): Groot and Warren's predictor, for particles in the cell list's order.
// v + shift f is rounded to single precision from the double value. With `ids` the ids too, in the
// same pass (each entry written whole). With forceOrder the forces are still in the order before the
// last sort (SortForces::Leave): particle k's force is f[forceOrder[k]].
void fillPredictedVelocities(const Particles& p, double shift, const std::vector<std::uint8_t>* frozenOfSpecies,
                             const std::uint32_t* forceOrder, bool ids, PairInputs& in);

// The pair loop's inputs: one set per process, refilled by every pair loop (which runs one at a time).
PairInputs& sharedPairInputs();

}  // namespace dpd
