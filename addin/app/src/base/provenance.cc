#include "cablefit/app/base/provenance.h"

#include <ctime>
#include <filesystem>
#include <mutex>

#include "cablefit/app/base/report_html.h"
#include "cablefit/core/base/errors.h"
#include "cablefit/formats/file_digest.h"

namespace cablefit::addin {
namespace {

std::mutex& CommandLineMutex() {
  static std::mutex mutex;
  return mutex;
}

std::string& StoredCommandLine() {
  static std::string line;
  return line;
}

// A word as a POSIX shell reads it back: bare when it holds only safe characters.
std::string ShellWord(const std::string& word) {
  if (word.empty()) return "''";
  bool safe = true;
  for (const unsigned char c : word) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '-' || c == '_' || c == '.' || c == '/' || c == '=' || c == ':' ||
                    c == ',' || c == '+' || c == '@' || c >= 0x80;
    safe = safe && ok;
  }
  if (safe) return word;
  std::string quoted = "'";
  for (const char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

}  // namespace

std::string ToolVersion() { return std::string("cablefit ") + CABLEFIT_VERSION; }

void SetCommandLine(int argc, const char* const* argv) {
  std::string line;
  for (int i = 0; i < argc; ++i) {
    // The binary as "cablefit" wherever it lives: the line names the tool, not the machine.
    const std::string word = i == 0 ? std::string("cablefit") : std::string(argv[i]);
    line += (i == 0 ? "" : " ") + ShellWord(word);
  }
  std::lock_guard lock(CommandLineMutex());
  StoredCommandLine() = line;
}

std::string CommandLine() {
  std::lock_guard lock(CommandLineMutex());
  return StoredCommandLine();
}

std::string UtcNow() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  char text[32] = "";
  if (gmtime_r(&now, &utc)) std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

nlohmann::json ProvenanceJson(const std::vector<std::pair<std::string, std::string>>& inputs) {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& [role, path] : inputs) {
    if (path.empty()) continue;
    nlohmann::json sha = nullptr;
    // Only a regular file has bytes to hash: reading a FIFO (a failed input of a batch) would
    // wait for a writer forever.
    std::error_code ec;
    if (std::filesystem::is_regular_file(path, ec)) {
      try {
        sha = FileSha256(path);
      } catch (const FileError&) {
        // The input was read a moment ago; if it is gone now, say so rather than fail the output.
      }
    }
    list.push_back({{"role", role}, {"path", path}, {"sha256", sha}});
  }
  return {{"tool", ToolVersion()},
          {"date", UtcNow()},
          {"command_line", CommandLine()},
          {"inputs", std::move(list)}};
}

std::string ProvenanceHtml(const nlohmann::json& provenance) {
  auto text = [&](const char* key) {
    const auto it = provenance.find(key);
    return it != provenance.end() && it->is_string() ? it->get<std::string>() : std::string();
  };
  std::string h = "<p class=\"provenance\">" + HtmlEscape(text("tool")) + " &middot; " +
                  HtmlEscape(text("date"));
  if (!text("command_line").empty())
    h += " &middot; <code>" + HtmlEscape(text("command_line")) + "</code>";
  const auto inputs = provenance.find("inputs");
  if (inputs != provenance.end() && inputs->is_array() && !inputs->empty()) {
    h += "<br>";
    bool first = true;
    for (const nlohmann::json& in : *inputs) {
      const std::string sha = in.value("sha256", nlohmann::json()).is_string()
                                  ? in.at("sha256").get<std::string>()
                                  : std::string("unreadable");
      h += std::string(first ? "" : "<br>") + HtmlEscape(in.value("role", "")) + " " +
           HtmlEscape(in.value("path", "")) + " <code>sha256 " + HtmlEscape(sha) + "</code>";
      first = false;
    }
  }
  return h + "</p>";
}

}  // namespace cablefit::addin
