#include "cablefit/app/provenance.h"

#include "cablefit/core/base/errors.h"
#include "cablefit/formats/file_digest.h"

namespace cablefit::addin {

std::string ToolVersion() { return std::string("cablefit ") + CABLEFIT_VERSION; }

nlohmann::json ProvenanceJson(const std::vector<std::pair<std::string, std::string>>& inputs) {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& [role, path] : inputs) {
    if (path.empty()) continue;
    nlohmann::json sha = nullptr;
    try {
      sha = FileSha256(path);
    } catch (const FileError&) {
      // The input was read a moment ago; if it is gone now, say so rather than fail the output.
    }
    list.push_back({{"role", role}, {"path", path}, {"sha256", sha}});
  }
  return {{"tool", ToolVersion()}, {"inputs", std::move(list)}};
}

}  // namespace cablefit::addin
