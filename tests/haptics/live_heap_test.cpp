// keep_large_blocks_mapped: a large block is mapped again after one was freed (glibc's dynamic
// threshold would have risen past its size and served it from the heap). Counted with
// mallinfo2's mapped blocks; the sanitizers bring their own allocator, so the test skips there.
#include <gtest/gtest.h>

#include <malloc.h>

#include <cstdlib>
#include <cstring>

#include "haptics/live_heap.h"

namespace ps {
namespace {

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr bool kOwnAllocator = true;
#else
constexpr bool kOwnAllocator = false;
#endif

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
  if (kOwnAllocator) GTEST_SKIP() << "a sanitizer's allocator replaces glibc's";
  keep_large_blocks_mapped();
  const std::size_t large = 3 * kLargeBlockBytes;
  EXPECT_EQ(mapped_while_held(large), 1u);
  EXPECT_EQ(mapped_while_held(large), 1u) << "the second block came from the heap";
  EXPECT_EQ(mapped_while_held(kLargeBlockBytes / 4), 0u) << "small blocks stay in the heap";
}

}  // namespace
}  // namespace ps
