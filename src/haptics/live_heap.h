// The heap of a program that runs for hours (run, the maze window, bench-haptics): see
// keep_large_blocks_mapped.
#pragma once

#include <cstddef>

namespace ps {

// Blocks of this size and over get a mapping of their own (mallopt(3) M_MMAP_THRESHOLD).
inline constexpr std::size_t kLargeBlockBytes = std::size_t{1} << 20;

// glibc raises its mmap threshold whenever a mapped block is freed (up to 32 MiB on 64-bit), so
// after the first world or image is freed, blocks of that size come from the heaps. Worlds of
// 100 MiB and more coming and going (the Virtual Universe's panel opening its worlds, a 4D turn
// rebuilding a surface) then fragment the heaps of several threads, and RSS climbs in steps that
// are no leak (docs/hardening.md, "Hours of running": the panel 2.5 % in an hour, its live heap
// flat). Setting the threshold fixes it at kLargeBlockBytes: every such block is mapped and
// given back when it is freed. Call once, before the threads start.
void keep_large_blocks_mapped();

}  // namespace ps
