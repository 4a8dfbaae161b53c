#include "tube_in_child.h"

#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "cablefit/core/base/errors.h"
#include "crash_probe.h"
#include "occt_tube.h"

namespace cablefit {
namespace {

constexpr int kSweepFailed = 3;  // child exit status: the file holds InvalidInput's message

// A fresh empty file in the temporary folder, removed when this goes out of scope.
class TempFile {
 public:
  TempFile() {
    std::string pattern =
        (std::filesystem::temp_directory_path() / "cablefit-tube-XXXXXX").string();
    const int fd = ::mkstemp(pattern.data());
    if (fd >= 0) {
      ::close(fd);
      path_ = pattern;
    }
  }
  ~TempFile() {
    if (!path_.empty()) std::remove(path_.c_str());
  }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;  // empty when no file could be created
};

}  // namespace

TopoDS_Shape MakeTubeSolidInChild(const TopoDS_Wire& spine, double diameter, double max_seconds) {
  const TempFile file;
  if (file.path().empty()) return MakeTubeSolid(spine, diameter);
  const auto outcome = RunInChildProcess(
      [&] {
        try {
          const TopoDS_Shape tube = MakeTubeSolid(spine, diameter);
          return BRepTools::Write(tube, file.path().c_str()) ? 0 : 4;
        } catch (const InvalidInput& e) {
          std::ofstream(file.path(), std::ios::trunc) << e.what();
          return kSweepFailed;
        }
      },
      max_seconds);
  if (!outcome) return MakeTubeSolid(spine, diameter);
  if (outcome->timed_out) {
    throw InvalidInput("the tube sweep did not finish within " +
                       std::to_string(static_cast<int>(max_seconds)) + " s");
  }
  if (outcome->signal != 0) {
    throw InvalidInput("the tube sweep crashed in OpenCASCADE (signal " +
                       std::to_string(outcome->signal) + ": " + ::strsignal(outcome->signal) +
                       ")");
  }
  if (outcome->exit_code == kSweepFailed) {
    std::ifstream in(file.path());
    std::stringstream message;
    message << in.rdbuf();
    throw InvalidInput(message.str());
  }
  TopoDS_Shape tube;
  BRep_Builder builder;
  if (outcome->exit_code != 0 || !BRepTools::Read(tube, file.path().c_str(), builder) ||
      tube.IsNull()) {
    throw InvalidInput("the tube sweep failed (exit status " +
                       std::to_string(outcome->exit_code) + ")");
  }
  return tube;
}

}  // namespace cablefit
