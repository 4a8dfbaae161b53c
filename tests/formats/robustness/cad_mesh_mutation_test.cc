// The OCCT- and assimp/CGAL-backed readers (ReadCadFile, ReadMeshFile) fed truncated and
// byte-mutated copies of the sample harness files, and a STEP with 10^5 entities: every call
// ends with a result or a one-line FileError/InvalidInput naming the file, within a bounded
// time; never another exception (an OCCT Standard_Failure or a CGAL assertion escaping the
// wrapper), a crash or a hang. Mutations are seeded, so a failure reproduces.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <sstream>
#include <string>

#include "cablefit/core/base/errors.h"
#include "cablefit/formats/cad_file.h"
#include "cablefit/formats/mesh_file.h"
#include "test_support.h"

namespace cablefit {
namespace {

namespace fs = std::filesystem;

std::string ReadBytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

void WriteBytes(const fs::path& p, const std::string& bytes) {
  std::ofstream(p, std::ios::binary | std::ios::trunc) << bytes;
}

struct Tally {
  int results = 0, input_errors = 0;
  double slowest = 0.0;  // [s]
};

// One call of `read` on `path`: a result or an InvalidInput whose message is one line naming
// the file; anything else fails the test with the variant's name.
void Expect(const std::string& variant, const fs::path& path, const std::function<void()>& read,
            double max_seconds, Tally* tally) {
  const auto t0 = std::chrono::steady_clock::now();
  try {
    read();
    ++tally->results;
  } catch (const InvalidInput& e) {
    ++tally->input_errors;
    const std::string what = e.what();
    EXPECT_EQ(what.find('\n'), std::string::npos) << variant << ": " << what;
    EXPECT_NE(what.find(path.filename().string()), std::string::npos) << variant << ": " << what;
  } catch (const std::exception& e) {
    ADD_FAILURE() << variant << ": escaped as a non-input exception: " << e.what();
  } catch (...) {
    ADD_FAILURE() << variant << ": escaped as an unknown exception";
  }
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  tally->slowest = std::max(tally->slowest, s);
  EXPECT_LT(s, max_seconds) << variant;
}

// Truncations at fixed fractions and `mutants` copies with 1..64 bytes overwritten (from the
// second kilobyte on for text formats, so the header mostly survives and the parser goes deep).
void MutateAndRead(const std::string& sample, int mutants, double max_seconds,
                   const std::function<void(const std::string&)>& read) {
  const fs::path source = testing::SourceDir() / "samples" / "harness" / sample;
  const std::string bytes = ReadBytes(source);
  ASSERT_GT(bytes.size(), 4096u) << source;
  const fs::path dir = testing::FreshTempDir(fs::path(sample).stem().string());
  const fs::path file = dir / ("mutant" + fs::path(sample).extension().string());
  Tally tally;
  for (const double f : {0.0, 0.001, 0.05, 0.25, 0.5, 0.75, 0.97, 0.9999}) {
    WriteBytes(file, bytes.substr(0, static_cast<std::size_t>(f * bytes.size())));
    Expect(sample + " truncated to " + std::to_string(f), file, [&] { read(file.string()); },
           max_seconds, &tally);
  }
  for (int k = 0; k < mutants; ++k) {
    std::mt19937 rng(1000 + k);
    std::string m = bytes;
    const int flips = 1 << (k % 7);  // 1 .. 64 bytes
    std::uniform_int_distribution<std::size_t> at(1024, m.size() - 1);
    std::uniform_int_distribution<int> value(0, 255);
    for (int i = 0; i < flips; ++i) m[at(rng)] = static_cast<char>(value(rng));
    WriteBytes(file, m);
    Expect(sample + " mutant seed " + std::to_string(1000 + k), file,
           [&] { read(file.string()); }, max_seconds, &tally);
  }
  std::printf("%s: %d tries, %d results, %d input errors, slowest %.2f s\n", sample.c_str(),
              tally.results + tally.input_errors, tally.results, tally.input_errors,
              tally.slowest);
}

TEST(CadMeshMutation, StepTruncatedAndMutated) {
  MutateAndRead("legacy_harness.step", 24, 60.0,
                [](const std::string& p) { (void)ReadCadFile(p); });
}

TEST(CadMeshMutation, IgesTruncatedAndMutated) {
  MutateAndRead("legacy_harness.igs", 24, 60.0,
                [](const std::string& p) { (void)ReadCadFile(p); });
}

TEST(CadMeshMutation, StlTruncatedAndMutated) {
  // The skeleton of a whole tube mesh takes seconds: fewer mutants than the CAD files.
  MutateAndRead("branched_tubes.stl", 8, 120.0,
                [](const std::string& p) { (void)ReadMeshFile(p, 1e-3); });
}

// 10^5 entities: one polyline of 10^5 - 2 points (CARTESIAN_POINTs), a plausible worst case of
// a "cable" exported point by point. It must come back as a result or an error in bounded time.
TEST(CadMeshMutation, StepWithOneHundredThousandEntities) {
  const fs::path dir = testing::FreshTempDir("step-entities");
  const fs::path file = dir / "many.step";
  const int points = 100000 - 2;
  {
    std::ofstream out(file);
    out << "ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION((''),'2;1');\n"
           "FILE_NAME('many.step','2026-01-01T00:00:00',(''),(''),'','','');\n"
           "FILE_SCHEMA(('AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }'));\nENDSEC;\nDATA;\n";
    for (int i = 0; i < points; ++i)
      out << '#' << (i + 1) << "=CARTESIAN_POINT('',(" << 0.001 * i << ",0.,"
          << 0.01 * std::sin(0.001 * i) << "));\n";
    out << '#' << (points + 1) << "=POLYLINE('cable',(";
    for (int i = 0; i < points; ++i) out << (i ? ",#" : "#") << (i + 1);
    out << "));\nENDSEC;\nEND-ISO-10303-21;\n";
  }
  Tally tally;
  Expect("100k entities", file, [&] { (void)ReadCadFile(file.string()); }, 120.0, &tally);
  std::printf("many.step: %s in %.2f s\n", tally.results ? "a result" : "an input error",
              tally.slowest);
}

}  // namespace
}  // namespace cablefit
