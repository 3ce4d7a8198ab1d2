// The reductions' outputs of two renders of one frame, equal bit for bit: what a way of drawing
// that must not change the image (the footprint rectangle, incremental frames) checks beside
// the pixels. Header only: the GL tests that need it include it.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "render/frame_stats.h"

namespace ps::test {

inline void expect_same_reductions(const FrameStats& s, const FrameStats& t, const std::string& where) {
  EXPECT_EQ(s.reference_normal, t.reference_normal) << where;
  EXPECT_EQ(s.displacement, t.displacement) << where;
  EXPECT_EQ(s.max_penetration_mm, t.max_penetration_mm) << where;
  EXPECT_EQ(s.probe_position, t.probe_position) << where;
  EXPECT_EQ(s.shadow_pixels, t.shadow_pixels) << where;
  EXPECT_EQ(s.penetrating_pixels, t.penetrating_pixels) << where;
}

}  // namespace ps::test
