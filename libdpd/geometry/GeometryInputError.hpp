#pragma once
// A geometry that cannot be used as given (unreadable file, wrong size, no physical group...). The
// dictionary reader (GeometryDictionary) turns it into an InputError naming the dictionary file, the
// line and `keyword`.
#include <stdexcept>
#include <string>

namespace dpd {

class GeometryInputError : public std::runtime_error {
public:
    GeometryInputError(std::string keyword, const std::string& message)
        : std::runtime_error(message), keyword_(std::move(keyword)) {}
    const std::string& keyword() const { return keyword_; }

private:
    std::string keyword_;
};

}  // namespace dpd
