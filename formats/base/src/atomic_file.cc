#include "cablefit/formats/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cerrno>
#include <cstring>
#include <fstream>

#include "cablefit/core/base/errors.h"

namespace cablefit {
namespace {

namespace fs = std::filesystem;

std::atomic<bool>& Durable() {
  static std::atomic<bool> durable{true};
  return durable;
}

// ".<name>.tmp.<pid>.<counter>.<random>": hidden, in the target's folder (so the rename stays
// on one file system), unique across threads (the counter), processes (the pid) and hosts
// sharing a folder (the random part).
fs::path TempPath(const fs::path& target) {
  static std::atomic<unsigned> counter{0};
  // The clock's nanoseconds, not std::random_device: opening the entropy source twice per
  // simulate cost a visible share of a process that is meant to take milliseconds.
  const auto ticks = static_cast<unsigned long long>(
      std::chrono::high_resolution_clock::now().time_since_epoch().count());
  // Built by appending: GCC 12's -Wrestrict misfires on "literal" + std::string.
  std::string name(1, '.');
  // At most 120 bytes of the target's name, so that the temporary name is not too long for the
  // file system whenever the target's own name is not (a cut UTF-8 sequence does not matter in
  // a name nobody reads).
  name += target.filename().string().substr(0, 120);
  name += ".tmp.";
  name += std::to_string(::getpid());
  name += '.';
  name += std::to_string(counter++);
  name += '.';
  name += std::to_string((ticks ^ (ticks >> 20)) % 1000000u);
  return target.parent_path() / name;
}

// fsync by path: the writers (std::ofstream, OCCT, assimp) do not expose their descriptors.
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

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
  const fs::path target(path_);
  const fs::path dir = target.parent_path();
  std::error_code ec;
  if (!dir.empty()) {
    fs::create_directories(dir, ec);
    if (ec) throw FileError(path_, "cannot create directory " + dir.string() + ": " + ec.message());
  }
  temp_ = TempPath(target);
}

AtomicFile::~AtomicFile() {
  if (committed_) return;
  std::error_code ignored;
  fs::remove(temp_, ignored);
}

void SetDurableWrites(bool durable) { Durable() = durable; }
bool DurableWrites() { return Durable(); }

void AtomicFile::Commit() {
  const bool durable = DurableWrites();
  if (durable) SyncFile(temp_, path_);
  // Without the sync, renaming over an existing file makes ext4 (auto_da_alloc) write the new
  // file's data out inside rename(): 0.15 ms on an idle disk, up to 8 ms on a busy one, several
  // times a whole simulate. An old regular file is moved aside first and removed after: never
  // a half-written file under the name, and a crash in between leaves both whole files.
  fs::path aside;
  struct stat old {};
  if (!durable && ::lstat(path_.c_str(), &old) == 0 && S_ISREG(old.st_mode)) {
    aside = TempPath(fs::path(path_));
    if (::rename(path_.c_str(), aside.c_str()) != 0) aside.clear();
  }
  std::error_code ec;
  fs::rename(temp_, path_, ec);
  if (ec) {
    if (!aside.empty()) (void)::rename(aside.c_str(), path_.c_str());
    throw FileError(path_, "cannot replace file: " + ec.message());
  }
  committed_ = true;
  if (!aside.empty()) (void)::unlink(aside.c_str());
  if (durable) SyncDirectory(fs::path(path_).parent_path());
}

void WriteFileAtomically(const std::string& path,
                         const std::function<void(std::ostream&)>& writer) {
  AtomicFile file(path);
  {
    std::ofstream out(file.temp_path(), std::ios::binary | std::ios::trunc);
    if (!out) throw FileError(path, "cannot open for writing: " + std::string(std::strerror(errno)));
    writer(out);
    out.flush();
    if (!out) throw FileError(path, "write failed (disk full?)");
    out.close();
    if (out.fail()) throw FileError(path, "closing the file failed");
  }
  file.Commit();
}

void WriteFileAtomically(const std::string& path, const std::string& contents) {
  WriteFileAtomically(path, [&contents](std::ostream& out) {
    out.write(contents.data(), static_cast<std::streamsize>(contents.size()));
  });
}

}  // namespace cablefit
