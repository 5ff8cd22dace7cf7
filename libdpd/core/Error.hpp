#pragma once
// Errors a user can act on. An InputError names the file, the line and the keyword; every tool turns
// it into one message on stderr and a non-zero exit status.
#include <stdexcept>
#include <string>

namespace dpd {

class InputError : public std::runtime_error {
public:
    InputError(std::string file, int line, std::string keyword, const std::string& message)
        : std::runtime_error(format(file, line, keyword, message)),
          file_(std::move(file)), line_(line), keyword_(std::move(keyword)) {}
    const std::string& file() const { return file_; }
    int line() const { return line_; }
    const std::string& keyword() const { return keyword_; }

private:
    static std::string format(const std::string& file, int line, const std::string& keyword,
                              const std::string& message) {
        std::string s = file;
        if (line > 0) s += ":" + std::to_string(line);
        if (!keyword.empty()) s += ": keyword '" + keyword + "'";
        return s + ": " + message;
    }
    std::string file_;
    int line_;
    std::string keyword_;
};

// A file that cannot be read or written (missing, unreadable, wrong layout).
class IoError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A run that went unstable (NaN, temperature runaway, particles inside walls).
class InstabilityError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace dpd
