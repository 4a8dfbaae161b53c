#include "test_support.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <fstream>
#include <sstream>

namespace cablefit::testing {

std::filesystem::path SourceDir() {
  if (const char* env = std::getenv("CABLEFIT_SOURCE_DIR")) return env;
  auto p = std::filesystem::current_path();
  while (!p.empty() && p != p.root_path()) {
    // The build tree mirrors core/ and formats/ under tests/: the source root is the one with
    // the architecture notes.
    if (std::filesystem::exists(p / "core") && std::filesystem::exists(p / "docs/architecture.md"))
      return p;
    p = p.parent_path();
  }
  return std::filesystem::current_path();
}

bool SanitizerBuild() {
#if defined(__SANITIZE_ADDRESS__)
  return true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(undefined_behavior_sanitizer)
  return true;
#else
  return false;
#endif
#else
  return false;
#endif
}

std::filesystem::path PublicCasesDir() {
  if (const char* env = std::getenv("CABLEFIT_PUBLIC_CASES")) return env;
  return SourceDir() / "tests" / "data" / "cases" / "public";
}

std::filesystem::path FreshTempDir(const std::string& tag) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = tag;
  if (info) name += std::string("-") + info->test_suite_name() + "-" + info->name();
  for (char& c : name)
    if (c == '/') c = '_';
  // The test binary's own path tells two checkouts apart: their suites may run at the same time
  // (a CI check of a clean clone beside a developer's build) and must not share folders.
  std::error_code ec;
  const std::string exe = std::filesystem::read_symlink("/proc/self/exe", ec).string();
  char tree[17];
  std::snprintf(tree, sizeof tree, "%08zx", std::hash<std::string>{}(exe) & 0xffffffffu);
  auto dir = std::filesystem::temp_directory_path() / ("cablefit-test-" + std::string(tree) + "-" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

std::string ReadTextFile(const std::filesystem::path& path) {
  std::ifstream f(path);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

::testing::AssertionResult MatricesNear(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b,
                                        double tol) {
  if (a.rows() != b.rows() || a.cols() != b.cols())
    return ::testing::AssertionFailure() << "shape " << a.rows() << "x" << a.cols() << " vs "
                                         << b.rows() << "x" << b.cols();
  const double err = (a - b).cwiseAbs().maxCoeff();
  if (err <= tol) return ::testing::AssertionSuccess();
  std::ostringstream os;
  os << "max abs difference " << err << " > " << tol;
  return ::testing::AssertionFailure() << os.str();
}

}  // namespace cablefit::testing
