// SHA-256 of a file's bytes: outputs name the exact inputs they came from, so that a result
// signed off today can be traced to the very CAD, case and config files behind it.
#pragma once

#include <string>

namespace cablefit {

/// Lower-case hex SHA-256 of the file's contents. Throws FileError(path, ...) when it cannot
/// be read.
std::string FileSha256(const std::string& path);

}  // namespace cablefit
