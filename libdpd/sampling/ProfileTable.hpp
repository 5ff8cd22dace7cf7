#pragma once
// Profiles as text tables, the form a person plots (gnuplot, numpy.loadtxt, pandas):
//
//   # z density densityErr ux uxErr uy uyErr uz uzErr kT kTErr count
//   -4.875 3.9871234567890123 0.0123... ...
//
// One header line starting with '#' names the columns (the first is the bin axis: x, y or z, and
// holds the bin centres); then one row per bin, numbers separated by blanks, written with 17
// significant digits so that reading them back gives the same doubles. Blank lines and further
// lines starting with '#' are ignored when reading.
#include "sampling/BinProfile.hpp"

#include <map>
#include <string>
#include <vector>

namespace dpd {

struct ProfileTableData {
    std::string file;                  // where it was read from (for messages)
    std::vector<std::string> names;    // column names in file order; names[0] is the axis
    std::map<std::string, std::vector<double>> columns;

    const std::string& axisName() const { return names.front(); }
    std::size_t rows() const { return columns.empty() ? 0 : columns.begin()->second.size(); }
    bool has(const std::string& name) const { return columns.count(name) > 0; }
    // IoError naming the file and the column when there is no such column.
    const std::vector<double>& column(const std::string& name) const;
};

// The column names of a profile table along the given axis ("x", "y" or "z").
std::vector<std::string> profileTableColumns(const std::string& axisName);
// The columns a profile with stress adds after those: e.g. for sigmaxz
//   sigmaxz sigmaxzErr sigmaxzKinetic sigmaxzKineticErr sigmaxzVirial sigmaxzVirialErr pressure pressureErr
std::vector<std::string> stressTableColumns(const std::string& stressName);

// Writes the profile atomically (temporary file in the same directory, then rename); creates the
// parent directory if needed. IoError when it cannot write; std::invalid_argument when the profile's
// arrays differ in length.
// A 2-D grid of bins (profile.centre2 set) gets the second axis as the second column (axis2Name),
// one row per bin, the first axis running fastest.
void writeProfileTable(const std::string& path, const std::string& axisName, const BinProfile& profile,
                       const std::string& axis2Name = "");

// Reads any table in this format (any column names). IoError naming the file when it cannot be read,
// has no header, repeats a column name or has no rows; IoError naming the file and the line for a row
// with the wrong number of values or a value that is not a number.
ProfileTableData readProfileTable(const std::string& path);

}  // namespace dpd
