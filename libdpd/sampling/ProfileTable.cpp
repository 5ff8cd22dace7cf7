#include "sampling/ProfileTable.hpp"

#include "io/AtomicFile.hpp"

#include "core/Error.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include <unistd.h>

namespace dpd {

namespace fs = std::filesystem;

namespace {

std::string formatNumber(double x) {
    char buffer[40];
    std::snprintf(buffer, sizeof buffer, "%.17g", x);
    return buffer;
}

std::vector<std::string> splitBlanks(const std::string& line) {
    std::istringstream in(line);
    std::vector<std::string> words;
    std::string w;
    while (in >> w) words.push_back(w);
    return words;
}

bool parseNumber(const std::string& s, double& out) {
    if (s.empty()) return false;
    char* end = nullptr;
    errno = 0;
    out = std::strtod(s.c_str(), &end);
    if (end != s.c_str() + s.size()) return false;
    // Underflow to a denormal or zero is harmless; overflow is not a number we wrote.
    return !(errno == ERANGE && std::abs(out) > 1.0);
}

bool isBlank(const std::string& line) { return line.find_first_not_of(" \t\r") == std::string::npos; }

bool isComment(const std::string& line) {
    const auto first = line.find_first_not_of(" \t");
    return first != std::string::npos && line[first] == '#';
}

}  // namespace

const std::vector<double>& ProfileTableData::column(const std::string& name) const {
    const auto it = columns.find(name);
    if (it == columns.end()) {
        std::string have;
        for (const auto& n : names) have += (have.empty() ? "" : " ") + n;
        throw IoError(file + ": the profile table has no column '" + name + "' (columns: " + have + ")");
    }
    return it->second;
}

std::vector<std::string> profileTableColumns(const std::string& axisName) {
    return {axisName, "density", "densityErr", "ux", "uxErr", "uy", "uyErr", "uz", "uzErr", "kT", "kTErr", "count"};
}

std::vector<std::string> stressTableColumns(const std::string& stressName) {
    return {stressName,         stressName + "Err",       stressName + "Kinetic", stressName + "KineticErr",
            stressName + "Virial", stressName + "VirialErr", "pressure",           "pressureErr"};
}

void writeProfileTable(const std::string& path, const std::string& axisName, const BinProfile& p,
                       const std::string& axis2Name) {
    const std::size_t n = p.centre.size();
    const bool grid = !p.centre2.empty();
    if (grid && (p.centre2.size() != n || axis2Name.empty()))
        throw std::invalid_argument("writeProfileTable: a 2-D grid needs one centre2 per bin and the second axis' name");
    for (const auto* v : {&p.density, &p.densityErr, &p.ux, &p.uxErr, &p.uy, &p.uyErr, &p.uz, &p.uzErr, &p.kT,
                          &p.kTErr, &p.count})
        if (v->size() != n) throw std::invalid_argument("writeProfileTable: the profile's arrays differ in length");
    if (p.hasStress && p.stress.size() != n)
        throw std::invalid_argument("writeProfileTable: the profile's stress has the wrong length");

    std::vector<std::string> names = profileTableColumns(axisName);
    if (grid) names.insert(names.begin() + 1, axis2Name);
    if (p.hasStress)
        for (const std::string& name : stressTableColumns(p.stressName)) names.push_back(name);
    std::string text = "#";
    for (const std::string& name : names) text += " " + name;
    text += "\n";
    for (std::size_t i = 0; i < n; ++i) {
        std::vector<double> row = {p.centre[i], p.density[i], p.densityErr[i], p.ux[i], p.uxErr[i], p.uy[i],
                                   p.uyErr[i],  p.uz[i],      p.uzErr[i],      p.kT[i], p.kTErr[i], p.count[i]};
        if (grid) row.insert(row.begin() + 1, p.centre2[i]);
        if (p.hasStress) {
            const StressPoint& s = p.stress[i];
            row.insert(row.end(), {s.shear, s.shearErr, s.shearKinetic, s.shearKineticErr, s.shearVirial,
                                   s.shearVirialErr, s.pressure, s.pressureErr});
        }
        bool first = true;
        for (double x : row) {
            text += (first ? "" : " ") + formatNumber(x);
            first = false;
        }
        text += "\n";
    }

    writeTextFileAtomically(path, text, true);
}

ProfileTableData readProfileTable(const std::string& path) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) throw IoError(path + ": profile table not found");
    std::ifstream in(path);
    if (!in) throw IoError(path + ": cannot open the profile table");

    ProfileTableData t;
    t.file = path;
    std::vector<std::vector<double>*> byIndex;
    std::string line;
    int lineNo = 0;
    while (std::getline(in, line)) {
        ++lineNo;
        if (isBlank(line)) continue;
        if (t.names.empty()) {
            if (!isComment(line))
                throw IoError(path + ":" + std::to_string(lineNo) +
                              ": expected the header line '# <axis> density densityErr ...' before the data");
            std::vector<std::string> names = splitBlanks(line.substr(line.find('#') + 1));
            if (names.empty()) throw IoError(path + ":" + std::to_string(lineNo) + ": the header names no columns");
            std::set<std::string> seen;
            for (const auto& name : names)
                if (!seen.insert(name).second)
                    throw IoError(path + ":" + std::to_string(lineNo) + ": column '" + name + "' appears twice");
            t.names = std::move(names);
            for (const auto& name : t.names) byIndex.push_back(&t.columns[name]);
            continue;
        }
        if (isComment(line)) continue;
        const std::vector<std::string> words = splitBlanks(line);
        if (words.size() != t.names.size())
            throw IoError(path + ":" + std::to_string(lineNo) + ": expected " + std::to_string(t.names.size()) +
                          " values (one per header column), found " + std::to_string(words.size()));
        for (std::size_t k = 0; k < words.size(); ++k) {
            double x;
            if (!parseNumber(words[k], x))
                throw IoError(path + ":" + std::to_string(lineNo) + ": '" + words[k] + "' in column '" + t.names[k] +
                              "' is not a number");
            byIndex[k]->push_back(x);
        }
    }
    if (in.bad()) throw IoError(path + ": reading the profile table failed");
    if (t.names.empty()) throw IoError(path + ": empty profile table (no header line)");
    if (t.rows() == 0) throw IoError(path + ": the profile table has a header but no rows");
    return t;
}

}  // namespace dpd
