#pragma once
// Text files written whole or not at all: the text goes to a temporary file beside the target,
// which is then renamed over it, so a reader never sees half a file and a failed write leaves the old
// file (or none) in place.
#include <string>

namespace dpd {

// Creates the parent directory if `createParent`; throws IoError naming the file on failure.
void writeTextFileAtomically(const std::string& path, const std::string& text, bool createParent = false);

}  // namespace dpd
