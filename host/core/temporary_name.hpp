#pragma once
// Outputs are written to a hidden temporary file beside their destination, then renamed into
// place, so that no reader ever sees a partial file. The temporary's name is derived from the
// destination's, and must itself be a legal name: a 254-byte output name plus ".XXXXXX" is not.
#include <string>

namespace lancer {

// A mkstemp() template in the directory of `path`: ".NAME.XXXXXX", NAME being the destination's
// file name, shortened (at a UTF-8 character boundary) where the whole would exceed the
// directory's limit on name length (NAME_MAX, 255 bytes on most file systems).
std::string temporary_template(const std::string& path);

}  // namespace lancer
