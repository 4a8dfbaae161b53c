#include "pipeline/relax_inputs.h"

#include <algorithm>
#include <filesystem>
#include <set>

#include "cablefit/app/input/input_kind.h"
#include "cablefit/app/output/output_folder.h"
#include "cablefit/formats/input_file.h"

namespace cablefit::addin {

namespace fs = std::filesystem;

std::vector<std::string> ExpandInputs(const std::vector<std::string>& inputs,
                                      std::vector<std::string>* failures) {
  std::vector<std::string> files;
  for (const std::string& p : inputs) {
    std::error_code ec;
    if (fs::is_directory(p, ec)) {
      std::vector<std::string> found;
      for (const auto& entry : fs::directory_iterator(p, ec)) {
        const std::string f = entry.path().string();
        if (entry.is_regular_file() && (IsCadPath(f) || IsKblPath(f) || IsMeshPath(f)))
          found.push_back(f);
      }
      std::sort(found.begin(), found.end());
      if (found.empty()) failures->push_back(p + ": folder holds no STEP, IGES, KBL or mesh file");
      files.insert(files.end(), found.begin(), found.end());
    } else if (fs::exists(p, ec)) {
      files.push_back(p);
    } else {
      failures->push_back(p + ": " + UnreachablePathProblem(p));
    }
  }
  return files;
}

std::vector<std::string> UniqueStems(const std::vector<std::string>& files) {
  std::set<std::string> used;
  std::vector<std::string> stems;
  for (const std::string& f : files) {
    const fs::path p(f);
    const std::string base = Utf8Prefix(p.stem().string(), kMaxStemBytes);
    std::string stem = base;
    if (used.count(stem))
      stem +=
          "-" + p.extension().string().substr(std::min<size_t>(1, p.extension().string().size()));
    for (int k = 2; used.count(stem); ++k) stem = base + "-" + std::to_string(k);
    used.insert(stem);
    stems.push_back(stem);
  }
  return stems;
}

}  // namespace cablefit::addin
