#include "io/AtomicFile.hpp"

#include "core/Error.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>

namespace dpd {

void writeTextFileAtomically(const std::string& path, const std::string& text, bool createParent) {
    namespace fs = std::filesystem;
    const fs::path target(path);
    std::error_code ec;
    if (createParent && target.has_parent_path()) {
        fs::create_directories(target.parent_path(), ec);
        if (ec) throw IoError("cannot write '" + path + "': cannot create its directory: " + ec.message());
    }
    const std::string tmp = path + ".tmp" + std::to_string(static_cast<long>(::getpid()));
    std::error_code ignored;
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) throw IoError("cannot write '" + path + "': cannot create '" + tmp + "'");
        out << text;
        out.close();
        if (!out) {
            fs::remove(tmp, ignored);
            throw IoError("cannot write '" + path + "': writing '" + tmp + "' failed");
        }
    }
    fs::rename(tmp, path, ec);
    if (ec) {
        fs::remove(tmp, ignored);
        throw IoError("cannot write '" + path + "': " + ec.message());
    }
}

}  // namespace dpd
