// Where a result came from, in every JSON and report the tool writes: the tool's version, when
// and by which command line it was made, and each input file with its SHA-256, so that a
// signed-off result can be traced to the exact files and the exact run behind it.
// Two runs on the same inputs differ only in `date` (and in `command_line` when it differs):
// compare the rest to see whether a result changed.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace cablefit::addin {

/// "cablefit <version>".
std::string ToolVersion();

/// Remembers this process's command line for CommandLine(); called once by the CLI's main.
/// The words are joined with single spaces, a word holding a space or a shell character is
/// put in single quotes, so that the line can be pasted back into a shell.
void SetCommandLine(int argc, const char* const* argv);

/// The command line given to SetCommandLine, "" when none was (a library user, a unit test).
std::string CommandLine();

/// The current time, UTC, as ISO 8601 to the second: "2026-12-03T03:52:07Z".
std::string UtcNow();

/// {"tool": ToolVersion(), "date": UtcNow(), "command_line": CommandLine(),
///  "inputs": [{"role", "path", "sha256"}...]} for (role, path) pairs; an empty path is left
/// out, an unreadable or non-regular file (a FIFO,
/// a folder) gets "sha256": null.
nlohmann::json ProvenanceJson(const std::vector<std::pair<std::string, std::string>>& inputs);

/// The same facts as one HTML paragraph for a report's footer or header: tool, date, command
/// line, and every input's name with its SHA-256.
std::string ProvenanceHtml(const nlohmann::json& provenance);

}  // namespace cablefit::addin
