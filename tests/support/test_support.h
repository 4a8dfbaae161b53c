// Shared test helpers: data paths, tolerant matrix comparison, expect-throws-with-message.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <filesystem>
#include <string>

namespace cablefit::testing {

/// Repository root (CABLEFIT_SOURCE_DIR from CTest, else found from the working directory).
std::filesystem::path SourceDir();
/// The public recording cases the tests read, copied into the repository so that a clone tests
/// itself (tests/data/cases/public; CABLEFIT_PUBLIC_CASES overrides it).
std::filesystem::path PublicCasesDir();
/// A fresh empty temporary directory unique to the running test.
std::filesystem::path FreshTempDir(const std::string& tag);

/// The whole content of a text file ("" when it cannot be read).
std::string ReadTextFile(const std::filesystem::path& path);

/// True in a sanitizer build (ASan/UBSan). Their checks make the rod numerics ~25x slower
/// (measured: the concealed corpus 1962 s instead of 80 s), so the long corpus tests run an even
/// subset of their cases there; the Release build runs every case.
bool SanitizerBuild();

::testing::AssertionResult MatricesNear(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b,
                                        double tol);

}  // namespace cablefit::testing

/// Expects `stmt` to throw `Exc` whose what() contains `substr`.
#define EXPECT_THROW_WITH(stmt, Exc, substr)                                               \
  do {                                                                                     \
    try {                                                                                  \
      stmt;                                                                                \
      ADD_FAILURE() << "expected " #Exc " from " #stmt;                                   \
    } catch (const Exc& e) {                                                               \
      EXPECT_NE(std::string(e.what()).find(substr), std::string::npos)                     \
          << "message: " << e.what();                                                      \
    }                                                                                      \
  } while (0)
