#include "cablefit/formats/input_file.h"

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "cablefit/core/base/cancellation.h"
#include "cablefit/core/base/errors.h"

namespace cablefit {

std::string UnreachablePathProblem(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code link_ec, ec;
  const bool link_exists = fs::exists(fs::symlink_status(path, link_ec));
  const fs::file_status target = fs::status(path, ec);
  if (fs::exists(target)) return "exists but could not be used";
  if (link_exists && fs::is_symlink(fs::symlink_status(path, link_ec))) {
    return ec ? "is a symbolic link that leads nowhere (" + ec.message() + ")"
              : "is a symbolic link to a missing file";
  }
  if (ec && ec != std::errc::no_such_file_or_directory) return "cannot be reached (" + ec.message() + ")";
  return "no such file or folder";
}

std::uint64_t CheckInputFile(const std::string& path, std::uint64_t max_bytes, const char* kind) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (!fs::exists(status)) throw FileError(path, UnreachablePathProblem(path));
  if (fs::is_directory(status)) throw FileError(path, "is a directory, expected a file");
  // A FIFO or device would block or never end: only plain files are read.
  if (!fs::is_regular_file(status)) throw FileError(path, "is not a regular file");
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) throw FileError(path, "cannot read its size (" + ec.message() + ")");
  if (size > max_bytes)
    throw FileError(path, "is " + std::to_string(size) + " bytes, more than the limit of " +
                              std::to_string(max_bytes) + " bytes for " + kind);
  return size;
}

std::string ReadInputFile(const std::string& path, std::uint64_t max_bytes, const char* kind) {
  const std::uint64_t size = CheckInputFile(path, max_bytes, kind);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError(path, "cannot open for reading");
  std::string data(static_cast<std::size_t>(size), '\0');
  // In chunks, so a batch item's --timeout also ends the read of a 2 GB scan on a slow disk.
  constexpr std::uint64_t kChunk = std::uint64_t{64} << 20;
  for (std::uint64_t done = 0; done < size;) {
    CheckCancelled();
    const std::uint64_t want = std::min(kChunk, size - done);
    in.read(data.data() + done, static_cast<std::streamsize>(want));
    // A file that shrank while being read is reported; one that grew is read up to its old size.
    if (static_cast<std::uint64_t>(in.gcount()) != want)
      throw FileError(path, "read error (file changed or unreadable while reading)");
    done += want;
  }
  return data;
}

}  // namespace cablefit
