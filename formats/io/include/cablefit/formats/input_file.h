// Reading a whole input file into memory with a size limit: every reader's allocations are
// bounded by the file's size, so the limit bounds the memory a hostile or broken file can take
// (a 2 GB "JSON", a FIFO, /dev/zero), and the check happens before a byte is read.
#pragma once

#include <cstdint>
#include <string>

namespace cablefit {

/// Size limits per kind of input [bytes]. Text formats (JSON, CSV) are small by nature (the
/// largest sample is 34 kB); at the limit the worst cases measured 0.70 GB peak (16 MiB of
/// nested JSON arrays) and 0.71 GB (16 MiB of one-cell CSV rows). A PLY scan takes its size
/// plus 24 bytes per point: at most ~6.3 GB for a 2 GiB binary file of float x, y, z.
inline constexpr std::uint64_t kMaxTextInputBytes = std::uint64_t{16} << 20;
inline constexpr std::uint64_t kMaxPlyInputBytes = std::uint64_t{2} << 30;

/// Why `path` cannot be used although it was named: "no such file or folder", or the system's
/// reason when something is there but cannot be reached (a loop of symbolic links, a dangling
/// link, a folder without permission), so that the user does not look for a typo.
std::string UnreachablePathProblem(const std::string& path);

/// Throws FileError(path, ...) unless `path` is a regular file of at most `max_bytes` bytes:
/// "no such file", "is a directory, expected a file", "is not a regular file", "is N bytes,
/// more than the limit of M bytes for <kind>". Returns the size.
std::uint64_t CheckInputFile(const std::string& path, std::uint64_t max_bytes, const char* kind);

/// CheckInputFile, then the whole file's bytes. Read errors throw FileError.
std::string ReadInputFile(const std::string& path, std::uint64_t max_bytes, const char* kind);

}  // namespace cablefit
