#include "sampling/ProfileGrid.hpp"

#include "core/Axis.hpp"
#include "io/AtomicFile.hpp"
#include "sampling/BinLayoutDictionary.hpp"

#include <array>
#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace dpd {

namespace {

std::string number(double x) {
    char buffer[40];
    std::snprintf(buffer, sizeof buffer, "%.17g", x);
    return buffer;
}

// VTK orders the cells x fastest, then y, then z; bins are ordered first axis fastest.
std::vector<std::size_t> vtkCellOfBin(const BinLayout& L) {
    std::array<int, 3> cells{1, 1, 1};
    cells[L.axis] = L.nBins;
    cells[L.axis2] = L.nBins2;
    std::vector<std::size_t> out(L.binCount());
    for (int j = 0; j < L.nBins2; ++j)
        for (int i = 0; i < L.nBins; ++i) {
            std::array<int, 3> c{0, 0, 0};
            c[L.axis] = i;
            c[L.axis2] = j;
            out[i + L.nBins * j] = c[0] + static_cast<std::size_t>(cells[0]) * (c[1] + static_cast<std::size_t>(cells[1]) * c[2]);
        }
    return out;
}

// One DataArray of the cells: `components` vectors, one per bin, in VTK's cell order.
std::string dataArray(const std::string& name, const std::vector<const std::vector<double>*>& components,
                      const std::vector<std::size_t>& cellOfBin) {
    const std::size_t n = cellOfBin.size();
    std::vector<double> values(n * components.size());
    for (std::size_t b = 0; b < n; ++b)
        for (std::size_t c = 0; c < components.size(); ++c) values[cellOfBin[b] * components.size() + c] = (*components[c])[b];
    std::string s = "        <DataArray type=\"Float64\" Name=\"" + name + "\" NumberOfComponents=\"" +
                    std::to_string(components.size()) + "\" format=\"ascii\">\n";
    for (std::size_t k = 0; k < values.size(); ++k) s += (k % 6 == 0 ? "          " : " ") + number(values[k]) + (k % 6 == 5 ? "\n" : "");
    if (values.size() % 6 != 0) s += "\n";
    return s + "        </DataArray>\n";
}

}  // namespace

void writeProfileImage(const std::string& path, const BinLayout& L, const BinProfile& p) {
    if (!L.twoAxes() || p.density.size() != static_cast<std::size_t>(L.binCount()))
        throw std::invalid_argument("writeProfileImage: needs a 2-D grid of bins and one profile entry per bin");
    std::array<int, 3> cells{0, 0, 0};
    std::array<double, 3> origin{0, 0, 0}, spacing{1, 1, 1};
    cells[L.axis] = L.nBins, origin[L.axis] = L.lo, spacing[L.axis] = L.width();
    cells[L.axis2] = L.nBins2, origin[L.axis2] = L.lo2, spacing[L.axis2] = L.width2();
    std::ostringstream extent, o, sp;
    extent << "0 " << cells[0] << " 0 " << cells[1] << " 0 " << cells[2];
    o << number(origin[0]) << " " << number(origin[1]) << " " << number(origin[2]);
    sp << number(spacing[0]) << " " << number(spacing[1]) << " " << number(spacing[2]);
    const std::vector<std::size_t> cellOfBin = vtkCellOfBin(L);
    std::string s = "<?xml version=\"1.0\"?>\n"
                    "<VTKFile type=\"ImageData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
                    "  <ImageData WholeExtent=\"" + extent.str() + "\" Origin=\"" + o.str() + "\" Spacing=\"" + sp.str() + "\">\n"
                    "    <Piece Extent=\"" + extent.str() + "\">\n"
                    "      <CellData Scalars=\"density\" Vectors=\"velocity\">\n";
    s += dataArray("density", {&p.density}, cellOfBin);
    s += dataArray("densityErr", {&p.densityErr}, cellOfBin);
    s += dataArray("velocity", {&p.ux, &p.uy, &p.uz}, cellOfBin);
    s += dataArray("velocityErr", {&p.uxErr, &p.uyErr, &p.uzErr}, cellOfBin);
    s += dataArray("kT", {&p.kT}, cellOfBin);
    s += dataArray("kTErr", {&p.kTErr}, cellOfBin);
    s += dataArray("count", {&p.count}, cellOfBin);
    s += "      </CellData>\n    </Piece>\n  </ImageData>\n</VTKFile>\n";
    writeTextFileAtomically(path, s, true);
}

BinProfile profileSection(const BinLayout& L, const BinProfile& p, double position) {
    const int i = L.binOf(position);
    if (!L.twoAxes() || i < 0) throw std::invalid_argument("profileSection: the position lies outside the 2-D bins");
    BinProfile out;
    out.samples = p.samples;
    out.blocksForErrors = p.blocksForErrors;
    const auto take = [&](const std::vector<double>& from, std::vector<double>& to) {
        for (int j = 0; j < L.nBins2; ++j) to.push_back(from[i + L.nBins * j]);
    };
    take(p.centre2, out.centre);
    take(p.density, out.density); take(p.densityErr, out.densityErr);
    take(p.ux, out.ux); take(p.uy, out.uy); take(p.uz, out.uz);
    take(p.uxErr, out.uxErr); take(p.uyErr, out.uyErr); take(p.uzErr, out.uzErr);
    take(p.kT, out.kT); take(p.kTErr, out.kTErr);
    take(p.count, out.count);
    return out;
}

std::string sectionFileName(const std::string& name, const BinLayout& L, double position) {
    char buffer[40];
    std::snprintf(buffer, sizeof buffer, "%g", position);
    return name + "_" + axisLetter(L.axis) + buffer + ".dat";
}

}  // namespace dpd
