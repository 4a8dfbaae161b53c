// Atomic file output: a reader never sees a half-written file, and a failed writer never
// destroys the previous version (write to a temp file in the same directory, fsync, rename).
#pragma once

#include <functional>
#include <ostream>
#include <string>

namespace cablefit {

/// Creates the parent directories of `path`, calls `writer` on a stream to a temporary file next
/// to `path`, flushes and fsyncs it, then renames it over `path`. If `writer` throws or any step
/// fails, the temporary file is removed, `path` is left as it was, and the exception propagates
/// (I/O failures are reported as FileError naming `path`).
void WriteFileAtomically(const std::string& path,
                         const std::function<void(std::ostream&)>& writer);

/// Writes `contents` to `path` atomically (see above).
void WriteFileAtomically(const std::string& path, const std::string& contents);

}  // namespace cablefit
