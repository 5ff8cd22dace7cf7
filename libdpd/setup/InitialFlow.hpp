#pragma once
// The mean flow a channel's fluid starts with (blockFrozenWallDict: fluid { initialFlow { ... } }).
//
//   initialFlow
//   {
//       type    poiseuille;     // none (default) | poiseuille | reversePoiseuille
//       nu      0.277;          // optional: kinematic viscosity; default the kinetic-theory estimate
//       axis          z;        // poiseuille between the walls of a geometry block (randomEquilWall),
//       wallPositions (-20 20); //   which are not planar walls of dpdProperties: their normal axis
//                               //   and positions along it (both or neither; walls at rest)
//   }
//
// Why: started from rest, plane Poiseuille flow reaches its steady profile only as its slowest mode
// decays, as exp(-pi^2 nu t / d^2): for d = 40 and nu = 0.27 that time is about 600, so a run
// from rest must wait thousands of time units before its profile can be sampled without a bias.
// Started from the laminar no-slip profile of the set body force, only the error of the viscosity
// estimate (a few per cent) and the slip have to relax. The same holds for the periodic reverse
// Poiseuille flow that measures the viscosity without walls (time scale (L/2)^2 / (pi^2 nu)).
#include "core/Box.hpp"
#include "core/Particles.hpp"

#include <Eigen/Core>
#include <cstddef>

namespace dpd {

class Dictionary;
struct DpdModel;

struct InitialFlow {
    enum class Type { none, poiseuille, reversePoiseuille };
    Type type = Type::none;
    int axis = -1;                    // the walls' normal axis, or the reverse-Poiseuille gradient axis
    double lower = 0.0, upper = 0.0;  // wall positions along it, or the box's ends
    Eigen::Vector3d g{0, 0, 0};     // body force per unit mass (along the walls)
    double nu = 0.0;

    // Poiseuille: the no-slip laminar profile u = g (s - lower)(upper - s) / (2 nu), zero outside the
    // walls. Reverse Poiseuille: the periodic steady profile of +g in the lower half of the box and
    // -g in the upper half, two such parabolas of opposite sign.
    Eigen::Vector3d velocityAt(double s) const;
};

// Reads `initialFlow` from the fluid's sub-dictionary (absent: none). A Poiseuille start needs two
// parallel planar walls at rest with opposite normals (or, without planar walls, axis and
// wallPositions) and a uniform body force along them; a reverse
// Poiseuille start needs that body force and no walls; anything else is an InputError naming the
// keyword. `density` is the fluid's, for the default viscosity.
InitialFlow readInitialFlow(const Dictionary& fluidDict, const DpdModel& model, const Box& box, int fluidSpecies,
                            double density);

// Adds the initial flow's velocity to particles [begin, end) (their thermal velocities stay).
void addInitialFlow(Particles& p, std::size_t begin, std::size_t end, const InitialFlow& flow);

}  // namespace dpd
