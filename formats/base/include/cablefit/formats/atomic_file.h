// Atomic file output, the one writer every format uses: a reader never sees a half-written file,
// a failed writer never destroys the previous version, and (durable writes, the default) a crash
// of the machine right after a successful write loses neither the contents nor the new name
// (write to a temporary file in the target's folder, fsync it, rename it over the target, fsync
// the folder).
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>
#include <string>

namespace cablefit {

/// One atomic replacement of `path`, for writers that want a file name (OCCT, assimp) rather
/// than a stream: write to temp_path(), then Commit(). The temporary file is a hidden sibling
/// of `path` whose name is unique per process and call (so threads and processes writing the
/// same folder never share one) and is removed again unless Commit() succeeded.
class AtomicFile {
 public:
  /// Creates the parent directories of `path` (FileError naming `path` if it cannot).
  explicit AtomicFile(std::string path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  const std::string& path() const { return path_; }
  const std::filesystem::path& temp_path() const { return temp_; }

  /// fsyncs the temporary file, renames it over path() and fsyncs the folder (without the
  /// fsyncs when DurableWrites() is off). FileError naming
  /// path() on failure (the temporary file is removed, path() is left as it was).
  void Commit();

 private:
  std::string path_;
  std::filesystem::path temp_;
  bool committed_ = false;
};

/// Whether commits fsync (default true). A command whose outputs are cheaper to make again than
/// to sync turns it off once, before it writes anything: `cablefit simulate`, whose two small
/// files took several times its solve to fsync (a device flush each, more under other I/O). The
/// writes stay atomic (rename): a crash of the process leaves the old file or the new one.
void SetDurableWrites(bool durable);
bool DurableWrites();

/// Creates the parent directories of `path`, calls `writer` on a stream to a temporary file next
/// to `path`, then commits it (see AtomicFile). If `writer` throws or any step fails, the
/// temporary file is removed, `path` is left as it was, and the exception propagates (I/O
/// failures are reported as FileError naming `path`).
void WriteFileAtomically(const std::string& path,
                         const std::function<void(std::ostream&)>& writer);

/// Writes `contents` (text or bytes) to `path` atomically (see above).
void WriteFileAtomically(const std::string& path, const std::string& contents);

}  // namespace cablefit
