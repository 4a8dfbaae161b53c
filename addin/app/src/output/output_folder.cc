#include "cablefit/app/output/output_folder.h"

#include <algorithm>
#include <cctype>
#include <set>

#include "cablefit/core/base/errors.h"

namespace fs = std::filesystem;

namespace cablefit::addin {
namespace {

bool Same(const fs::path& a, const fs::path& b) {
  std::error_code ec;
  return fs::equivalent(a, b, ec) && !ec;
}

std::string Lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

std::string Utf8Prefix(const std::string& text, std::size_t max_bytes) {
  if (text.size() <= max_bytes) return text;
  std::size_t end = max_bytes;
  // Back off over continuation bytes (10xxxxxx) to the start of the cut sequence.
  while (end > 0 && (static_cast<unsigned char>(text[end]) & 0xC0) == 0x80) --end;
  return text.substr(0, end);
}

std::string SafeFileName(const std::string& name, const std::string& fallback) {
  std::string out;
  for (char c : name) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '.' || c == '_' || c == '-';
    out += ok ? c : '_';
  }
  if (out.empty() || out == "." || out == "..") out = fallback;
  return Utf8Prefix(out, kMaxStemBytes);
}

std::vector<std::string> UniqueNames(const std::vector<std::string>& names,
                                     const std::vector<std::string>& reserved) {
  std::set<std::string> used;
  for (const std::string& r : reserved) used.insert(Lower(r));
  std::vector<std::string> unique;
  unique.reserve(names.size());
  for (const std::string& name : names) {
    std::string candidate = name;
    for (int k = 2; used.count(Lower(candidate)) != 0; ++k) candidate = name + "-" + std::to_string(k);
    used.insert(Lower(candidate));
    unique.push_back(candidate);
  }
  return unique;
}

OutputFolder::OutputFolder(const std::string& out, const std::vector<std::string>& inputs)
    : out_(out) {
  if (out.empty()) throw InvalidInput("--out: the output folder name is empty");
  std::error_code ec;
  if (fs::exists(out_, ec) && !fs::is_directory(out_, ec)) {
    throw InvalidInput("--out " + out + ": exists and is not a folder");
  }
  AddInputs(inputs);
  for (const fs::path& in : inputs_) {
    if (Same(in, out_)) {
      throw InvalidInput("--out " + out + ": is the input " + in.string() +
                         "; write the results to another folder (inputs are never overwritten "
                         "and outputs never read as inputs)");
    }
  }
}

void OutputFolder::AddInputs(const std::vector<std::string>& inputs) {
  for (const std::string& in : inputs) inputs_.emplace_back(in);
}

void OutputFolder::CheckFile(const fs::path& output) const {
  for (const fs::path& in : inputs_) {
    if (Same(in, output)) {
      throw InvalidInput("--out " + out_.string() + ": the output " + output.string() +
                         " would replace the input " + in.string() +
                         "; write the results to another folder");
    }
  }
}

void OutputFolder::CheckFolder(const fs::path& output) const {
  std::error_code ec;
  for (const fs::path& in : inputs_) {
    const bool is_folder = fs::is_directory(in, ec);
    const fs::path holder = is_folder ? in : in.parent_path().empty() ? fs::path(".") : in.parent_path();
    if (Same(holder, output)) {
      throw InvalidInput("--out " + out_.string() + ": the output folder " + output.string() +
                         " is the input folder " + holder.string() +
                         "; write the results to another folder");
    }
  }
}

void CheckSummaryJsonPath(const std::string& path, const std::vector<std::string>& inputs) {
  if (path.empty()) throw InvalidInput("--summary-json: the file name is empty");
  std::error_code ec;
  if (fs::is_directory(path, ec))
    throw InvalidInput("--summary-json " + path + ": is a folder; name a file");
  for (const std::string& in : inputs) {
    if (fs::equivalent(in, path, ec) && !ec)
      throw InvalidInput("--summary-json " + path + ": is the input " + in +
                         "; write the summary to another file");
  }
}

}  // namespace cablefit::addin
