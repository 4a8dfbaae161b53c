#include "cablefit/formats/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>

#include "cablefit/core/base/errors.h"

namespace cablefit {
namespace {

namespace fs = std::filesystem;

std::string UniqueSuffix() {
  // pid + counter + random: unique across threads and across engineers writing the same folder.
  static std::atomic<unsigned> counter{0};
  std::random_device rd;
  return ".tmp." + std::to_string(::getpid()) + "." + std::to_string(counter++) + "." +
         std::to_string(rd() % 1000000u);
}

// fsync by path: std::ofstream does not expose its descriptor.
void SyncFile(const fs::path& file, const std::string& reported_path) {
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0)
    throw FileError(reported_path, std::string("cannot reopen temporary file for sync: ") +
                                       std::strerror(errno));
  const int rc = ::fsync(fd);
  const int err = errno;
  ::close(fd);
  if (rc != 0) throw FileError(reported_path, std::string("fsync failed: ") + std::strerror(err));
}

void SyncDirectory(const fs::path& dir) {
  // Best effort: makes the rename durable; some file systems refuse fsync on directories.
  const int fd = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  (void)::fsync(fd);
  ::close(fd);
}

}  // namespace

void WriteFileAtomically(const std::string& path,
                         const std::function<void(std::ostream&)>& writer) {
  const fs::path target(path);
  const fs::path dir = target.parent_path();
  std::error_code ec;
  if (!dir.empty()) {
    fs::create_directories(dir, ec);
    if (ec) throw FileError(path, "cannot create directory " + dir.string() + ": " + ec.message());
  }
  const fs::path temp = fs::path(target.string() + UniqueSuffix());
  try {
    {
      std::ofstream out(temp, std::ios::binary | std::ios::trunc);
      if (!out) throw FileError(path, "cannot open for writing: " + std::string(std::strerror(errno)));
      writer(out);
      out.flush();
      if (!out) throw FileError(path, "write failed (disk full?)");
      out.close();
      if (out.fail()) throw FileError(path, "closing the file failed");
    }
    SyncFile(temp, path);
    fs::rename(temp, target, ec);
    if (ec) throw FileError(path, "cannot replace file: " + ec.message());
  } catch (...) {
    fs::remove(temp, ec);
    throw;
  }
  SyncDirectory(dir);
}

void WriteFileAtomically(const std::string& path, const std::string& contents) {
  WriteFileAtomically(path, [&contents](std::ostream& out) {
    out.write(contents.data(), static_cast<std::streamsize>(contents.size()));
  });
}

}  // namespace cablefit
