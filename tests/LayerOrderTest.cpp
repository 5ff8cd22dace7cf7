// libdpd's folders point one way: a folder includes only the folders below it in libdpd/LAYERS
// (and itself), and every folder is listed there.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

const fs::path kLibrary = fs::path(DPD_SOURCE_DIR) / "libdpd";

// Folder name -> its level, from the bottom (0).
std::map<std::string, int> readLayers() {
    std::ifstream in(kLibrary / "LAYERS");
    std::map<std::string, int> level;
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream words(line.substr(0, line.find('#')));
        std::string folder;
        if (words >> folder) level.emplace(folder, static_cast<int>(level.size()));
    }
    return level;
}

// The project folders a file includes ("folder/File.hpp").
std::vector<std::string> includedFolders(const fs::path& file) {
    static const std::regex include(R"(^\s*#\s*include\s*"([A-Za-z0-9_]+)/)");
    std::ifstream in(file);
    std::vector<std::string> folders;
    std::string line;
    std::smatch m;
    while (std::getline(in, line))
        if (std::regex_search(line, m, include)) folders.push_back(m[1]);
    return folders;
}

}  // namespace

TEST(LayerOrder, EveryFolderIsListed) {
    const auto level = readLayers();
    ASSERT_GT(level.size(), 10u);
    for (const auto& entry : fs::directory_iterator(kLibrary))
        if (entry.is_directory()) EXPECT_TRUE(level.count(entry.path().filename().string())) << entry.path();
}

TEST(LayerOrder, NoFolderIncludesOneAboveIt) {
    const auto level = readLayers();
    int checked = 0;
    for (const auto& entry : fs::recursive_directory_iterator(kLibrary)) {
        if (!entry.is_regular_file()) continue;
        const std::string ext = entry.path().extension().string();
        if (ext != ".hpp" && ext != ".cpp" && ext != ".tpp") continue;
        const std::string folder = fs::relative(entry.path(), kLibrary).begin()->string();
        ASSERT_TRUE(level.count(folder)) << folder;
        for (const std::string& included : includedFolders(entry.path())) {
            ASSERT_TRUE(level.count(included)) << entry.path() << " includes from " << included << "/, not in LAYERS";
            EXPECT_LE(level.at(included), level.at(folder))
                << fs::relative(entry.path(), kLibrary) << " includes " << included << "/, a layer above " << folder << "/";
            ++checked;
        }
    }
    EXPECT_GT(checked, 100);  // the includes were found at all
}
