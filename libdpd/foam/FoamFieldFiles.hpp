#pragma once
// Reading what OpenFOAM wrote (ascii): the internal field of a volVectorField (<time>/U, <time>/C of
// postProcess -func writeCellCentres), the raw files of a `sets` function object
// (postProcessing/<name>/<time>/<line>_U.xy, columns x y z Ux Uy Uz with axis xyz), and the time
// directories of a case. Every problem is an IoError naming the file.
#include <Eigen/Core>

#include <string>
#include <vector>

namespace dpd {

// The cell values of internalField: "uniform (a b c)" (repeated nCellsIfUniform times; -1: once) or
// "nonuniform List<vector> N ( (a b c) ... )".
std::vector<Eigen::Vector3d> readFoamVectorField(const std::string& path, long nCellsIfUniform = -1);

struct FoamSampledLine {
    std::string file;
    std::vector<Eigen::Vector3d> points;
    std::vector<Eigen::Vector3d> values;
};
FoamSampledLine readFoamSampledLine(const std::string& path);

// The latest time directory of an OpenFOAM case other than 0 ("" when there is none).
std::string latestFoamTime(const std::string& foamCase);

}  // namespace dpd
