// Many STEP and IGES reads at once in worker threads, as relax does with a batch, while another
// thread keeps the allocator busy. Each read starts the crash-probe helper; a helper that
// inherits a lock held by another thread at the moment it is started never finishes, so the
// probe's time limit below would report "did not finish" instead of reading the file.
#include <gtest/gtest.h>

#include <atomic>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "cablefit/formats/cad_file.h"
#include "test_support.h"

namespace cablefit {
namespace {

TEST(CadParallelRead, ManyThreadsReadingAtOnceAllFinishWithTheSameCables) {
  const std::vector<std::string> files = {
      (testing::SourceDir() / "samples/harness/legacy_harness.step").string(),
      (testing::SourceDir() / "samples/harness/legacy_harness.igs").string()};
  CadReadOptions options;
  options.probe_seconds = 120;  // a healthy probe of these files takes well under a second
  std::vector<std::size_t> expected_cables;
  for (const std::string& f : files) expected_cables.push_back(ReadCadFile(f, options).cables.size());

  const int threads = 4;
  const int reads_per_thread = testing::SanitizerBuild() ? 2 : 6;
  std::atomic<bool> stop{false};
  std::thread churn([&] {  // allocations and frees on another thread during every spawn
    while (!stop) {
      std::vector<std::unique_ptr<char[]>> blocks;
      for (int i = 0; i < 256; ++i) blocks.emplace_back(new char[64 + 97 * i]);
    }
  });
  std::vector<std::string> failures(threads);
  std::vector<std::thread> workers;
  for (int t = 0; t < threads; ++t) {
    workers.emplace_back([&, t] {
      for (int r = 0; r < reads_per_thread; ++r) {
        const std::size_t k = static_cast<std::size_t>(t + r) % files.size();
        try {
          const HarnessDrawing drawing = ReadCadFile(files[k], options);
          if (drawing.cables.size() != expected_cables[k]) {
            failures[t] += files[k] + ": " + std::to_string(drawing.cables.size()) + " cables; ";
          }
        } catch (const std::exception& e) {
          failures[t] += std::string(e.what()) + "; ";
        }
      }
    });
  }
  for (std::thread& w : workers) w.join();
  stop = true;
  churn.join();
  for (int t = 0; t < threads; ++t) EXPECT_EQ(failures[t], "") << "thread " << t;
}

}  // namespace
}  // namespace cablefit
