// The --out folder of a command, checked before anything is written. A run must never replace
// one of its own inputs (a relaxed STEP over the drawing it came from, a simulated centre line
// over the recorded one) and must never read its earlier outputs as new inputs, so an output
// folder that is an input folder, or an output file that is an input file, is a usage error.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace cablefit::addin {

/// The longest a stem of output names may be [bytes]: with the longest suffix a command adds,
/// a name stays well within the 255 bytes file systems allow.
inline constexpr std::size_t kMaxStemBytes = 150;

/// The first at most `max_bytes` bytes of `text`, never cutting a UTF-8 sequence in two.
std::string Utf8Prefix(const std::string& text, std::size_t max_bytes);

/// Output folder names: characters outside [A-Za-z0-9._-] become '_' so that a name can never
/// leave the output folder; "", "." and ".." become `fallback`; cut to kMaxStemBytes.
std::string SafeFileName(const std::string& name, const std::string& fallback);

/// Makes every name unique within the run and different from every `reserved` name, compared
/// without regard to case (the output may be copied to a case-insensitive file system): the
/// second "left_cable" becomes "left_cable-2", then "-3"... Names are taken in the given order,
/// so the result depends only on that order.
std::vector<std::string> UniqueNames(const std::vector<std::string>& names,
                                     const std::vector<std::string>& reserved);

/// Throws InvalidInput before any work when --summary-json `path` cannot be the run summary:
/// empty, an existing folder, or one of `inputs`.
void CheckSummaryJsonPath(const std::string& path, const std::vector<std::string>& inputs);

class OutputFolder {
 public:
  /// Throws InvalidInput ("--out ...: <why>") when `out` is empty, is an existing non-folder, or
  /// is one of `inputs` (files or folders as named on the command line or found in them).
  OutputFolder(const std::string& out, const std::vector<std::string>& inputs);

  const std::filesystem::path& path() const { return out_; }

  /// Throws InvalidInput when the file `output`, which this run will write, is one of the inputs.
  void CheckFile(const std::filesystem::path& output) const;

  /// Throws InvalidInput when the folder `output`, which this run will write into, is an input
  /// folder or holds an input file directly (a case's own folder).
  void CheckFolder(const std::filesystem::path& output) const;

  /// Adds inputs found after the command line was read (case and recording files).
  void AddInputs(const std::vector<std::string>& inputs);

 private:
  std::filesystem::path out_;
  std::vector<std::filesystem::path> inputs_;  // as given, compared by std::filesystem::equivalent
};

}  // namespace cablefit::addin
