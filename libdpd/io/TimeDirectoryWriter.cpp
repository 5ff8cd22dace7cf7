#include "io/TimeDirectoryWriter.hpp"

#include "core/Error.hpp"

#include <fcntl.h>
#include <stdio.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <system_error>

namespace dpd {

namespace fs = std::filesystem;

namespace {

const std::string kWriting = ".writing-";
const std::string kReplaced = ".replaced-";

void removeAll(const fs::path& p) {
    std::error_code error;
    fs::remove_all(p, error);
    if (error) throw IoError(p.string() + ": cannot remove: " + error.message());
}

// Puts the finished directory in place of `target`, which may exist.
void moveIntoPlace(const fs::path& finished, const fs::path& target) {
    std::error_code error;
    if (!fs::exists(target, error)) {
        fs::rename(finished, target, error);
        if (error) throw IoError(target.string() + ": cannot rename " + finished.string() + " to it: " + error.message());
        return;
    }
    // Both exist: swap them in one step, then the old one (now under the temporary name) goes.
    if (renameat2(AT_FDCWD, finished.c_str(), AT_FDCWD, target.c_str(), RENAME_EXCHANGE) != 0)
        throw IoError(target.string() + ": cannot replace it with " + finished.string() + ": " + std::strerror(errno));
    const fs::path old = target.parent_path() / (kReplaced + target.filename().string());
    removeAll(old);
    fs::rename(finished, old, error);  // out of the way first, so that a kill leaves no ".writing-" time
    removeAll(error ? finished : old);
}

}  // namespace

void writeTimeDirectory(const std::string& caseDir, const std::string& time,
                        const std::function<void(const std::string&)>& fill) {
    const fs::path temporary = fs::path(caseDir) / (kWriting + time);
    removeAll(temporary);
    fill(temporary.string());
    moveIntoPlace(temporary, fs::path(caseDir) / time);
}

void removeUnfinishedTimeDirectories(const std::string& caseDir) {
    std::error_code error;
    for (const auto& entry : fs::directory_iterator(caseDir, error)) {
        const std::string name = entry.path().filename().string();
        if (name.rfind(kWriting, 0) == 0 || name.rfind(kReplaced, 0) == 0) removeAll(entry.path());
    }
}

}  // namespace dpd
