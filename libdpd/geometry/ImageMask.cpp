#include "geometry/ImageMask.hpp"

#include "core/Axis.hpp"
#include "geometry/GeometryInputError.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace dpd {

double PixelMask::at(int i, int j) const {
    i = ((i % width) + width) % width;
    j = ((j % height) + height) % height;
    return solid[static_cast<std::size_t>(j) * width + i];
}

void PixelMask::smooth() {
    // The binomial kernel (1 4 6 4 1)/16 along each axis in turn, wrapping periodically.
    constexpr double w[5] = {1.0 / 16, 4.0 / 16, 6.0 / 16, 4.0 / 16, 1.0 / 16};
    for (int axis = 0; axis < 2; ++axis) {
        std::vector<double> out(solid.size());
        for (int j = 0; j < height; ++j)
            for (int i = 0; i < width; ++i) {
                double sum = 0.0;
                for (int k = -2; k <= 2; ++k) sum += w[k + 2] * (axis == 0 ? at(i + k, j) : at(i, j + k));
                out[static_cast<std::size_t>(j) * width + i] = sum;
            }
        solid = std::move(out);
    }
}

PixelMask thresholdImage(const GreyImage& image, const ImageMaskSettings& s) {
    PixelMask m;
    m.width = image.width;
    m.height = image.height;
    m.solid.resize(image.grey.size());
    for (int row = 0; row < image.height; ++row)
        for (int col = 0; col < image.width; ++col) {
            const double g = image.at(row, col);
            const bool solid = s.useThreshold ? (s.solidBelow ? g < s.threshold : g > s.threshold)
                                              : std::find(s.solidValues.begin(), s.solidValues.end(), g) != s.solidValues.end();
            m.solid[static_cast<std::size_t>(image.height - 1 - row) * image.width + col] = solid ? 1.0 : 0.0;
        }
    return m;
}

namespace {

void checkCoversBox(const PixelMask& m, const GeometryFrame& frame, double pixelSize, const std::string& source) {
    const double size[2] = {m.width * pixelSize, m.height * pixelSize};
    for (int k = 0; k < 2; ++k)
        if (std::abs(size[k] - frame.period[k]) > 1e-6 * frame.period[k]) {
            std::ostringstream os;
            os << source << ": the " << m.width << " x " << m.height << " pixel image at pixelSize " << pixelSize
               << " is " << size[0] << " x " << size[1] << " but the box is " << frame.period[0] << " x "
               << frame.period[1] << " along " << axisLetter(frame.axes[0]) << " and " << axisLetter(frame.axes[1])
               << ": the mask must cover the box exactly";
            throw GeometryInputError("pixelSize", os.str());
        }
}

// Solid where the bilinear interpolation of the (smoothed) pixel-centre values is >= 1/2.
bool bilinearSolid(const PixelMask& m, double pixelSize, const Eigen::Vector3d& p) {
    const double x = p.x() / pixelSize - 0.5, y = p.y() / pixelSize - 0.5;
    const int i = static_cast<int>(std::floor(x)), j = static_cast<int>(std::floor(y));
    const double tx = x - i, ty = y - j;
    const double v = (1 - tx) * (1 - ty) * m.at(i, j) + tx * (1 - ty) * m.at(i + 1, j) + (1 - tx) * ty * m.at(i, j + 1) +
                     tx * ty * m.at(i + 1, j + 1);
    return v >= 0.5;
}

Eigen::Vector3d unit(const Eigen::Vector3d& v) { return v / v.norm(); }

// Normal of the segment a-b turned towards `fluidSide`.
Eigen::Vector3d normalTowards(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& fluidSide) {
    Eigen::Vector3d n = unit(Eigen::Vector3d(a.y() - b.y(), b.x() - a.x(), 0.0));
    return n.dot(fluidSide - 0.5 * (a + b)) >= 0.0 ? n : Eigen::Vector3d(-n);
}

// The marching-squares contour at 1/2 through every square of four neighbouring pixel centres, its
// vertices where the values interpolated linearly along an edge cross 1/2.
void addContour(const PixelMask& m, double h, BoundaryFacets& facets) {
    for (int j = 0; j < m.height; ++j)
        for (int i = 0; i < m.width; ++i) {
            // Corners counter-clockwise from (i, j); edge e joins corner e and corner e+1.
            const int ci[4] = {i, i + 1, i + 1, i}, cj[4] = {j, j, j + 1, j + 1};
            Eigen::Vector3d corner[4];
            double value[4];
            bool solid[4];
            for (int c = 0; c < 4; ++c) {
                corner[c] = Eigen::Vector3d((ci[c] + 0.5) * h, (cj[c] + 0.5) * h, 0.0);
                value[c] = m.at(ci[c], cj[c]);
                solid[c] = value[c] >= 0.5;
            }
            const auto cross = [&](int e) {
                const int f = (e + 1) % 4;
                const double t = (0.5 - value[e]) / (value[f] - value[e]);
                return Eigen::Vector3d(corner[e] + t * (corner[f] - corner[e]));
            };
            std::vector<int> crossed;
            for (int e = 0; e < 4; ++e)
                if (solid[e] != solid[(e + 1) % 4]) crossed.push_back(e);
            if (crossed.size() == 2) {
                Eigen::Vector3d fluidCentre(0, 0, 0);
                int nFluid = 0;
                for (int c = 0; c < 4; ++c)
                    if (!solid[c]) { fluidCentre += corner[c]; ++nFluid; }
                const Eigen::Vector3d a = cross(crossed[0]), b = cross(crossed[1]);
                facets.addSegment(a, b, normalTowards(a, b, fluidCentre / nFluid));
            } else if (crossed.size() == 4) {
                // Saddle: the centre value (the mean, as the bilinear interpolant has it) decides
                // which diagonal pair is joined; each corner of the other kind is cut off alone.
                const bool centreSolid = 0.25 * (value[0] + value[1] + value[2] + value[3]) >= 0.5;
                for (int c = 0; c < 4; ++c) {
                    if (solid[c] == centreSolid) continue;
                    const Eigen::Vector3d a = cross((c + 3) % 4), b = cross(c);
                    const Eigen::Vector3d away = solid[c] ? Eigen::Vector3d(2.0 * 0.5 * (a + b) - corner[c]) : corner[c];
                    facets.addSegment(a, b, normalTowards(a, b, away));
                }
            }
        }
}

}  // namespace

SolidGeometry imageMaskGeometry(const GreyImage& image, const ImageMaskSettings& s, const Box& box,
                                const std::string& source, double searchReach) {
    const GeometryFrame frame = GeometryFrame::planar(box, s.extrudeAxis, s.origin);
    auto mask = std::make_shared<PixelMask>(thresholdImage(image, s));
    if (s.smooth) mask->smooth();
    checkCoversBox(*mask, frame, s.pixelSize, source);
    BoundaryFacets facets(frame);
    addContour(*mask, s.pixelSize, facets);
    const double h = s.pixelSize;
    return SolidGeometry(frame, [mask, h](const Eigen::Vector3d& p) { return bilinearSolid(*mask, h, p); },
                         std::move(facets), source, searchReach);
}

}  // namespace dpd
