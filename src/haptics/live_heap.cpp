#include "haptics/live_heap.h"

#include <malloc.h>

namespace ps {

void keep_large_blocks_mapped() { mallopt(M_MMAP_THRESHOLD, static_cast<int>(kLargeBlockBytes)); }

}  // namespace ps
