#pragma once
// Files the geometry tests write for themselves: grey images as PGM (text), PNG and TIFF written
// byte by byte here (uncompressed, rows from the top as both formats define), so that the readers
// are checked against the formats themselves and not against VTK's own writers; gmsh .geo text.
#include "core/Box.hpp"
#include "core/Error.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace geometryTest {

namespace fs = std::filesystem;

// A 2-D box (the x-z plane) from the origin to (lx, lz).
inline dpd::Box box2d(double lx, double lz) {
    dpd::Box b;
    b.dimension = 2;
    b.lo = Eigen::Vector3d(0, -0.5, 0);
    b.hi = Eigen::Vector3d(lx, 0.5, lz);
    return b;
}

// rows[0] is the top row of the picture; grey levels 0..255.
using Picture = std::vector<std::vector<int>>;

// A square picture of n x n pixels, fluid (255) but for its top and bottom solidRows rows (0): a channel
// along the columns' axis between two solid walls.
inline Picture channelPicture(int n, int solidRows) {
    Picture pic(n, std::vector<int>(n, 255));
    for (int r = 0; r < solidRows; ++r)
        for (int c = 0; c < n; ++c) pic[r][c] = pic[n - 1 - r][c] = 0;
    return pic;
}

inline void writeText(const std::string& path, const std::string& text) {
    fs::create_directories(fs::path(path).parent_path());
    std::ofstream(path) << text;
}

inline void writeBytes(const std::string& path, const std::vector<std::uint8_t>& bytes) {
    fs::create_directories(fs::path(path).parent_path());
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), bytes.size());
}

inline void writePgm(const std::string& path, const Picture& rows) {
    std::string s = "P2\n# written by the geometry tests\n" + std::to_string(rows[0].size()) + " " +
                    std::to_string(rows.size()) + "\n255\n";
    for (const auto& row : rows) {
        for (const int g : row) s += std::to_string(g) + " ";
        s += "\n";
    }
    writeText(path, s);
}

inline void putBigEndian(std::vector<std::uint8_t>& out, std::uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<std::uint8_t>(v >> shift));
}

inline std::uint32_t crc32(const std::uint8_t* p, std::size_t n) {
    std::uint32_t c = 0xffffffffu;
    for (std::size_t i = 0; i < n; ++i) {
        c ^= p[i];
        for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
    }
    return c ^ 0xffffffffu;
}

inline void pngChunk(std::vector<std::uint8_t>& out, const char* type, const std::vector<std::uint8_t>& data) {
    putBigEndian(out, static_cast<std::uint32_t>(data.size()));
    const std::size_t start = out.size();
    out.insert(out.end(), type, type + 4);
    out.insert(out.end(), data.begin(), data.end());
    putBigEndian(out, crc32(out.data() + start, out.size() - start));
}

// 8-bit greyscale PNG; the image data as a zlib stream of stored (uncompressed) deflate blocks.
inline void writePng(const std::string& path, const Picture& rows) {
    const auto width = static_cast<std::uint32_t>(rows[0].size()), height = static_cast<std::uint32_t>(rows.size());
    std::vector<std::uint8_t> raw;   // each row: filter byte 0, then the pixels
    for (const auto& row : rows) {
        raw.push_back(0);
        for (const int g : row) raw.push_back(static_cast<std::uint8_t>(g));
    }
    std::vector<std::uint8_t> z{0x78, 0x01};
    for (std::size_t pos = 0; pos < raw.size(); pos += 65535) {
        const auto len = static_cast<std::uint16_t>(std::min<std::size_t>(65535, raw.size() - pos));
        z.push_back(pos + len == raw.size() ? 1 : 0);
        z.insert(z.end(), {static_cast<std::uint8_t>(len), static_cast<std::uint8_t>(len >> 8),
                           static_cast<std::uint8_t>(~len), static_cast<std::uint8_t>(~len >> 8)});
        z.insert(z.end(), raw.begin() + pos, raw.begin() + pos + len);
    }
    std::uint32_t a = 1, b = 0;  // Adler-32
    for (const auto byte : raw) { a = (a + byte) % 65521; b = (b + a) % 65521; }
    putBigEndian(z, (b << 16) | a);
    std::vector<std::uint8_t> png{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    std::vector<std::uint8_t> header;
    putBigEndian(header, width);
    putBigEndian(header, height);
    header.insert(header.end(), {8, 0, 0, 0, 0});  // 8-bit grey, deflate, no filter, no interlace
    pngChunk(png, "IHDR", header);
    pngChunk(png, "IDAT", z);
    pngChunk(png, "IEND", {});
    writeBytes(path, png);
}

// Baseline little-endian TIFF: 8-bit grey (BlackIsZero), uncompressed, one strip, rows from the top.
inline void writeTiff(const std::string& path, const Picture& rows) {
    const auto width = static_cast<std::uint32_t>(rows[0].size()), height = static_cast<std::uint32_t>(rows.size());
    std::vector<std::uint8_t> t{'I', 'I', 42, 0};
    const auto put16 = [&](std::uint32_t v) { t.insert(t.end(), {static_cast<std::uint8_t>(v), static_cast<std::uint8_t>(v >> 8)}); };
    const auto put32 = [&](std::uint32_t v) { put16(v & 0xffff); put16(v >> 16); };
    const std::uint32_t pixelsAt = 8;
    put32(pixelsAt + width * height);  // the directory follows the pixels
    for (const auto& row : rows)
        for (const int g : row) t.push_back(static_cast<std::uint8_t>(g));
    const std::vector<std::array<std::uint32_t, 3>> entries{  // tag, type (3 short, 4 long), value
        {256, 4, width}, {257, 4, height}, {258, 3, 8}, {259, 3, 1}, {262, 3, 1}, {273, 4, pixelsAt},
        {277, 3, 1}, {278, 4, height}, {279, 4, width * height}};
    put16(static_cast<std::uint32_t>(entries.size()));
    for (const auto& [tag, type, value] : entries) {
        put16(tag);
        put16(type);
        put32(1);
        if (type == 3) { put16(value); put16(0); } else put32(value);
    }
    put32(0);
    writeBytes(path, t);
}

// The message of the dpd::InputError that f throws ("" if none).
template <class F>
std::string inputError(F&& f) {
    try {
        f();
    } catch (const dpd::InputError& e) {
        return e.what();
    }
    return "";
}

// A fresh directory per test (ctest runs tests in parallel), removed afterwards.
class ScratchDirectory : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::temp_directory_path() / ("dpdGeometry-" + std::string(info->name()) + "-" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    fs::path dir_;
};

}  // namespace geometryTest
