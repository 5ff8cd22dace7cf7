#include "geometry/ImageMask.hpp"

#include "geometry/GeometryInputError.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace dpd {

bool PixelMask::at(int i, int j) const {
    i = ((i % width) + width) % width;
    j = ((j % height) + height) % height;
    return solid[static_cast<std::size_t>(j) * width + i] != 0;
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
            m.solid[static_cast<std::size_t>(image.height - 1 - row) * image.width + col] = solid ? 1 : 0;
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
               << frame.period[1] << " along " << "xyz"[frame.axes[0]] << " and " << "xyz"[frame.axes[1]]
               << ": the mask must cover the box exactly";
            throw GeometryInputError("pixelSize", os.str());
        }
}

// Solid where the bilinear interpolation of the pixel-centre values is >= 1/2.
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

// The marching-squares contour at 1/2 through every square of four neighbouring pixel centres.
void addContour(const PixelMask& m, double h, BoundaryFacets& facets) {
    for (int j = 0; j < m.height; ++j)
        for (int i = 0; i < m.width; ++i) {
            // Corners counter-clockwise from (i, j); edge e joins corner e and corner e+1.
            const int ci[4] = {i, i + 1, i + 1, i}, cj[4] = {j, j, j + 1, j + 1};
            Eigen::Vector3d corner[4];
            bool solid[4];
            for (int c = 0; c < 4; ++c) {
                corner[c] = Eigen::Vector3d((ci[c] + 0.5) * h, (cj[c] + 0.5) * h, 0.0);
                solid[c] = m.at(ci[c], cj[c]);
            }
            std::vector<int> crossed;
            for (int e = 0; e < 4; ++e)
                if (solid[e] != solid[(e + 1) % 4]) crossed.push_back(e);
            if (crossed.empty()) continue;
            const auto mid = [&](int e) { return Eigen::Vector3d(0.5 * (corner[e] + corner[(e + 1) % 4])); };
            if (crossed.size() == 2) {
                Eigen::Vector3d fluidCentre(0, 0, 0);
                int nFluid = 0;
                for (int c = 0; c < 4; ++c)
                    if (!solid[c]) { fluidCentre += corner[c]; ++nFluid; }
                const Eigen::Vector3d a = mid(crossed[0]), b = mid(crossed[1]);
                facets.addSegment(a, b, normalTowards(a, b, fluidCentre / nFluid));
            } else {
                // Checkerboard: the interpolant is exactly 1/2 on the two lines through the square's
                // centre, so the contour is the four half-lines from the edge midpoints to the centre.
                const Eigen::Vector3d centre = 0.25 * (corner[0] + corner[1] + corner[2] + corner[3]);
                for (int e = 0; e < 4; ++e) {
                    const Eigen::Vector3d fluidCorner = solid[e] ? corner[(e + 1) % 4] : corner[e];
                    facets.addSegment(mid(e), centre, normalTowards(mid(e), centre, fluidCorner));
                }
            }
        }
}

}  // namespace

SolidGeometry imageMaskGeometry(const GreyImage& image, const ImageMaskSettings& s, const Box& box,
                                const std::string& source, double searchReach) {
    const GeometryFrame frame = GeometryFrame::planar(box, s.extrudeAxis, s.origin);
    auto mask = std::make_shared<PixelMask>(thresholdImage(image, s));
    checkCoversBox(*mask, frame, s.pixelSize, source);
    BoundaryFacets facets(frame);
    addContour(*mask, s.pixelSize, facets);
    const double h = s.pixelSize;
    return SolidGeometry(frame, [mask, h](const Eigen::Vector3d& p) { return bilinearSolid(*mask, h, p); },
                         std::move(facets), source, searchReach);
}

}  // namespace dpd
