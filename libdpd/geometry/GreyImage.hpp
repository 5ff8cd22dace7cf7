#pragma once
// A 2-D image as grey levels, read through VTK's image readers: PNG (vtkPNGReader), PGM/PPM/PBM
// (vtkPNMReader) and TIFF (vtkTIFFReader), chosen by the file's extension. Colour images are turned
// to grey with the luminance weights 0.299 R + 0.587 G + 0.114 B; an alpha channel is ignored.
//
// Rows are stored as the image is seen: row 0 is the TOP row (the first row of a PNG or PGM file),
// column 0 the left column.
#include <string>
#include <vector>

namespace dpd {

struct GreyImage {
    int width = 0, height = 0;
    std::vector<double> grey;  // width * height, row by row from the top

    double at(int row, int column) const { return grey[static_cast<std::size_t>(row) * width + column]; }
};

// Throws GeometryInputError (keyword "file") for a missing, unreadable or unsupported file, or a
// 3-D image stack.
GreyImage readGreyImage(const std::string& path);

}  // namespace dpd
