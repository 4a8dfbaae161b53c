// The allocator tuning has to reach glibc: a block of a few megabytes then comes from the heap,
// not from a mapping of its own (glibc's default maps blocks from 128 kB up).
#include "cablefit/formats/allocator_tuning.h"

#include <gtest/gtest.h>

#include <cstdlib>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace cablefit {
namespace {

#if defined(__GLIBC__)
TEST(AllocatorTuning, AFewMegabytesComeFromTheHeapNotFromAMappingOfTheirOwn) {
  TuneAllocatorForSolves();
  const std::size_t mapped_before = mallinfo2().hblks;
  void* block = std::malloc(8 << 20);
  ASSERT_NE(block, nullptr);
  EXPECT_EQ(mallinfo2().hblks, mapped_before);
  std::free(block);
}
#endif

}  // namespace
}  // namespace cablefit
