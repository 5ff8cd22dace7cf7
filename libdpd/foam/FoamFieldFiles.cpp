#include "foam/FoamFieldFiles.hpp"

#include "core/Error.hpp"
#include "io/TimeDirectories.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>

namespace dpd {

namespace {

std::string readWhole(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw IoError("cannot open '" + path + "'");
    std::ostringstream os;
    os << in.rdbuf();
    return os.str();
}

// Numbers of the text with parentheses read as blanks.
std::istringstream numberStream(std::string text) {
    std::replace(text.begin(), text.end(), '(', ' ');
    std::replace(text.begin(), text.end(), ')', ' ');
    return std::istringstream(text);
}

Eigen::Vector3d readVector(std::istream& in, const std::string& path) {
    Eigen::Vector3d v;
    if (!(in >> v.x() >> v.y() >> v.z())) throw IoError(path + ": internalField: expected a vector (x y z)");
    return v;
}

}  // namespace

std::vector<Eigen::Vector3d> readFoamVectorField(const std::string& path, long nCellsIfUniform) {
    const std::string text = readWhole(path);
    if (text.find("format      binary") != std::string::npos || text.find("format binary") != std::string::npos)
        throw IoError(path + ": binary format: write the case with writeFormat ascii");
    const std::size_t key = text.find("internalField");
    if (key == std::string::npos) throw IoError(path + ": no internalField (not an OpenFOAM field file?)");
    const std::size_t end = text.find("boundaryField", key);
    std::string body = text.substr(key + 13, end == std::string::npos ? std::string::npos : end - key - 13);
    std::istringstream words(body);
    std::string kind;
    words >> kind;
    std::vector<Eigen::Vector3d> values;
    if (kind == "uniform") {
        std::istringstream in = numberStream(body.substr(body.find("uniform") + 7));
        values.assign(static_cast<std::size_t>(std::max(1L, nCellsIfUniform)), readVector(in, path));
        return values;
    }
    if (kind != "nonuniform") throw IoError(path + ": internalField is neither uniform nor nonuniform");
    const std::size_t list = body.find("List<vector>");
    if (list == std::string::npos) throw IoError(path + ": internalField is not a List<vector> (not a vector field?)");
    std::istringstream in = numberStream(body.substr(list + 12));
    long n = -1;
    if (!(in >> n) || n < 0) throw IoError(path + ": internalField: expected the number of values after List<vector>");
    values.reserve(static_cast<std::size_t>(n));
    for (long i = 0; i < n; ++i) values.push_back(readVector(in, path));
    return values;
}

FoamSampledLine readFoamSampledLine(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw IoError("cannot open '" + path + "' (did simpleFoam run with the sets function object?)");
    FoamSampledLine l;
    l.file = path;
    std::string line;
    int lineNo = 0;
    while (std::getline(in, line)) {
        ++lineNo;
        if (line.find_first_not_of(" \t\r") == std::string::npos || line[line.find_first_not_of(" \t")] == '#') continue;
        std::istringstream row(line);
        Eigen::Vector3d p, v;
        if (!(row >> p.x() >> p.y() >> p.z() >> v.x() >> v.y() >> v.z()))
            throw IoError(path + ":" + std::to_string(lineNo) + ": expected x y z Ux Uy Uz (setFormat raw, axis xyz)");
        l.points.push_back(p);
        l.values.push_back(v);
    }
    if (l.points.size() < 2) throw IoError(path + ": fewer than 2 sampled points");
    return l;
}

std::string latestFoamTime(const std::string& foamCase) {
    const std::vector<TimeDirectory> times = listTimes(foamCase);
    if (times.empty() || times.back().value == 0.0) return "";
    return times.back().name;
}

}  // namespace dpd
