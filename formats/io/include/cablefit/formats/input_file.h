// Reading a whole input file into memory with a size limit: every reader's allocations are
// bounded by the file's size, so the limit bounds the memory a hostile or broken file can take
// (a 2 GB "JSON", a FIFO, /dev/zero), and the check happens before a byte is read.
#pragma once

#include <cstdint>
#include <string>

namespace cablefit {

/// Size limits per kind of input [bytes]. Text formats (JSON, CSV) are small by nature (the
/// largest sample is 34 kB); a parsed document takes at most ~70x its text in the worst case
/// (deeply nested arrays), so 16 MiB keeps that under ~1.2 GB. A PLY scan takes its size plus
/// 24 bytes per point (at most 3x a binary file's size).
inline constexpr std::uint64_t kMaxTextInputBytes = std::uint64_t{16} << 20;
inline constexpr std::uint64_t kMaxPlyInputBytes = std::uint64_t{2} << 30;

/// Throws FileError(path, ...) unless `path` is a regular file of at most `max_bytes` bytes:
/// "no such file", "is a directory, expected a file", "is not a regular file", "is N bytes,
/// more than the limit of M bytes for <kind>". Returns the size.
std::uint64_t CheckInputFile(const std::string& path, std::uint64_t max_bytes, const char* kind);

/// CheckInputFile, then the whole file's bytes. Read errors throw FileError.
std::string ReadInputFile(const std::string& path, std::uint64_t max_bytes, const char* kind);

}  // namespace cablefit
