#include "geometry/GreyImage.hpp"

#include "geometry/GeometryInputError.hpp"

#include <vtkImageData.h>
#include <vtkImageReader2.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkPNMReader.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkTIFFReader.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>

namespace dpd {

namespace {

vtkSmartPointer<vtkImageReader2> readerFor(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    if (ext == ".png") return vtkSmartPointer<vtkPNGReader>::New();
    if (ext == ".pgm" || ext == ".ppm" || ext == ".pbm" || ext == ".pnm") return vtkSmartPointer<vtkPNMReader>::New();
    if (ext == ".tif" || ext == ".tiff") return vtkSmartPointer<vtkTIFFReader>::New();
    throw GeometryInputError("file", path + ": unsupported image type '" + ext + "' (expected .png, .pgm, .ppm, .tif or .tiff)");
}

double luminance(vtkImageData* data, int x, int y, int components) {
    if (components <= 2) return data->GetScalarComponentAsDouble(x, y, 0, 0);  // grey (+ alpha)
    return 0.299 * data->GetScalarComponentAsDouble(x, y, 0, 0) + 0.587 * data->GetScalarComponentAsDouble(x, y, 0, 1) +
           0.114 * data->GetScalarComponentAsDouble(x, y, 0, 2);
}

// VTK reads only binary PNM (P5, P6): the plain-text grey map (P2) is read here.
bool isPlainPgm(const std::string& path) {
    std::ifstream in(path);
    std::string magic;
    return in >> magic && magic == "P2";
}

GreyImage readPlainPgm(const std::string& path) {
    std::ifstream in(path);
    std::vector<long> numbers;   // width, height, maximum, then the pixels
    std::string word;
    in >> word;   // P2
    while (in >> word) {
        if (word[0] == '#') {   // a comment runs to the end of its line
            std::getline(in, word);
            continue;
        }
        try {
            numbers.push_back(std::stol(word));
        } catch (const std::exception&) {
            throw GeometryInputError("file", path + ": '" + word + "' is not a number in a plain PGM (P2) file");
        }
    }
    if (numbers.size() < 3 || numbers[0] < 1 || numbers[1] < 1 ||
        numbers.size() != 3 + static_cast<std::size_t>(numbers[0] * numbers[1]))
        throw GeometryInputError("file", path + ": a plain PGM (P2) file needs width, height, maximum and width x height grey levels");
    GreyImage image;
    image.width = static_cast<int>(numbers[0]);
    image.height = static_cast<int>(numbers[1]);
    image.grey.assign(numbers.begin() + 3, numbers.end());
    return image;
}

}  // namespace

GreyImage readGreyImage(const std::string& path) {
    if (!std::filesystem::is_regular_file(path)) throw GeometryInputError("file", path + ": no such image file");
    const auto reader = readerFor(path);
    if (vtkPNMReader::SafeDownCast(reader) != nullptr && isPlainPgm(path)) return readPlainPgm(path);
    // CanReadFile checks the file's signature, so a damaged file is refused before VTK complains.
    if (reader->CanReadFile(path.c_str()) == 0)
        throw GeometryInputError("file", path + ": not a readable " + reader->GetDescriptiveName() + " file");
    reader->SetFileName(path.c_str());
    reader->Update();
    if (reader->GetErrorCode() != 0) throw GeometryInputError("file", path + ": VTK could not decode the image");
    vtkImageData* data = reader->GetOutput();
    int dims[3] = {0, 0, 0};
    data->GetDimensions(dims);
    if (dims[0] < 1 || dims[1] < 1 || data->GetPointData()->GetScalars() == nullptr)
        throw GeometryInputError("file", path + ": the image is empty or could not be decoded");
    if (dims[2] != 1) throw GeometryInputError("file", path + ": a stack of images (3-D) is not a 2-D mask");
    GreyImage image;
    image.width = dims[0];
    image.height = dims[1];
    image.grey.resize(static_cast<std::size_t>(dims[0]) * dims[1]);
    const int components = data->GetNumberOfScalarComponents();
    // VTK's PNG and PNM readers put the picture's top row at the largest y; its TIFF reader puts it at
    // y = 0 (honouring the file's Orientation tag, top-left by default). Bring both to "row 0 is the
    // top"; the tests write all three formats byte by byte to hold this.
    const bool topAtYZero = vtkTIFFReader::SafeDownCast(reader) != nullptr;
    for (int row = 0; row < image.height; ++row)
        for (int col = 0; col < image.width; ++col)
            image.grey[static_cast<std::size_t>(row) * image.width + col] =
                luminance(data, col, topAtYZero ? row : image.height - 1 - row, components);
    return image;
}

}  // namespace dpd
