// keep_large_blocks_mapped: a large block is mapped again after one was freed (glibc's dynamic
// threshold would have risen past its size and served it from the heap). Counted with
// mallinfo2's mapped blocks. A sanitizer brings its own allocator, which glibc's counts do not
// see: the test skips when a 64 MiB block (glibc maps every block over 32 MiB) is not counted.
#include <gtest/gtest.h>

#include <malloc.h>

#include <cstdlib>
#include <cstring>

#include "haptics/live_heap.h"

namespace ps {
namespace {

// Allocates, touches and frees one block; how many more blocks were mapped while it lived.
std::size_t mapped_while_held(std::size_t bytes) {
  const std::size_t before = mallinfo2().hblks;
  void* p = std::malloc(bytes);
  EXPECT_NE(p, nullptr);
  std::memset(p, 1, bytes);
  const std::size_t during = mallinfo2().hblks;
  std::free(p);
  return during - before;
}

TEST(LiveHeapTest, ALargeBlockIsMappedEvenAfterOneWasFreed) {
  if (mapped_while_held(std::size_t{64} << 20) != 1u) GTEST_SKIP() << "not glibc's allocator (a sanitizer's)";
  keep_large_blocks_mapped();
  const std::size_t large = 3 * kLargeBlockBytes;
  EXPECT_EQ(mapped_while_held(large), 1u);
  EXPECT_EQ(mapped_while_held(large), 1u) << "the second block came from the heap";
  EXPECT_EQ(mapped_while_held(kLargeBlockBytes / 4), 0u) << "small blocks stay in the heap";
}

}  // namespace
}  // namespace ps
