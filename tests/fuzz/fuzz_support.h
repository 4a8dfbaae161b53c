// Shared by the libFuzzer targets: the readers take paths, so each input is written to a file in
// a per-process scratch folder (on tmpfs when there is one); and the one rule every reader must
// keep: bytes it cannot use are reported as cablefit::InvalidInput (FileError), nothing else.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "cablefit/core/base/errors.h"

namespace cablefit::fuzz {

/// The scratch folder of this process, created on first use.
inline const std::filesystem::path& ScratchDir() {
  static const std::filesystem::path dir = [] {
    std::error_code ec;
    std::filesystem::path base = "/dev/shm";
    if (!std::filesystem::is_directory(base, ec)) base = std::filesystem::temp_directory_path();
    std::filesystem::path d = base / ("cablefit-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    std::atexit([] {
      std::error_code ignored;
      std::filesystem::remove_all(ScratchDir(), ignored);
    });
    return d;
  }();
  return dir;
}

/// Writes `size` bytes to ScratchDir()/name and returns its path.
inline std::string WriteScratch(const std::string& name, const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path p = ScratchDir() / name;
  if (p.parent_path() != ScratchDir()) std::filesystem::create_directories(p.parent_path());
  std::ofstream out(p, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return p.string();
}

inline std::string WriteScratch(const std::string& name, const std::string& text) {
  return WriteScratch(name, reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
}

/// Copies a committed file (path relative to the source tree) to ScratchDir()/name, so inputs
/// can name a valid neighbour (a recording, a material library).
inline void CopySample(const std::string& source_relative, const std::string& name) {
  const std::filesystem::path to = ScratchDir() / name;
  std::filesystem::create_directories(to.parent_path());
  std::filesystem::copy_file(std::filesystem::path(CABLEFIT_SOURCE_DIR) / source_relative, to,
                             std::filesystem::copy_options::overwrite_existing);
}

/// Runs `read`; an InvalidInput is the expected answer to bad bytes, any other exception is a
/// bug and aborts (libFuzzer then saves the input as a crash).
template <typename Read>
void ExpectOnlyInputErrors(const char* reader, Read&& read) {
  try {
    read();
  } catch (const InvalidInput& e) {
    // A one-line message is part of the contract: the CLI prints it as one line.
    const std::string what = e.what();
    if (what.find('\n') != std::string::npos) {
      std::fprintf(stderr, "%s: multi-line error message: %s\n", reader, what.c_str());
      std::abort();
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s threw a non-input exception: %s\n", reader, e.what());
    std::abort();
  } catch (...) {
    std::fprintf(stderr, "%s threw an unknown exception\n", reader);
    std::abort();
  }
}

}  // namespace cablefit::fuzz
