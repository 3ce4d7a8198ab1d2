// GL test fixture: each test runs once per headless backend with a fresh 4.5 core context.
//   class FooGLTest : public ps::test::GlTest {};
//   TEST_P(FooGLTest, Bar) { ... }
//   PS_INSTANTIATE_HEADLESS_BACKENDS(FooGLTest);
// A backend that cannot create a context FAILS the test (never skips): on these machines both
// EGL surfaceless and OSMesa work, so a missing one is a broken environment worth seeing.
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <ostream>
#include <string>

#include "gl/context.h"

namespace ps::gl {
// gtest prints parameters with this (found by ADL): "egl" instead of "4-byte object <01-00 ...>".
inline void PrintTo(Backend backend, std::ostream* os) { *os << backend_name(backend); }
}  // namespace ps::gl

namespace ps::test {

class GlTest : public ::testing::TestWithParam<ps::gl::Backend> {
 protected:
  void SetUp() override;
  void TearDown() override;

  ps::gl::Context& context() { return *context_; }

 private:
  std::unique_ptr<ps::gl::Context> context_;
};

// True when `context` renders with Mesa's llvmpipe, the software rasteriser that the project's
// exact-bytes claims rest on (docs/gl-stack.md). Tests whose expected numbers hold only there
// check it and GTEST_SKIP with the reason elsewhere, so the suite runs on a machine with a GPU.
bool is_llvmpipe(const ps::gl::Context& context);

// Parameter name for gtest: "egl" / "osmesa".
std::string backend_param_name(const ::testing::TestParamInfo<ps::gl::Backend>& info);

}  // namespace ps::test

#define PS_INSTANTIATE_HEADLESS_BACKENDS(Suite)                                          \
  INSTANTIATE_TEST_SUITE_P(Headless, Suite,                                              \
                           ::testing::Values(::ps::gl::Backend::kEgl,                    \
                                             ::ps::gl::Backend::kOsmesa),                \
                           ::ps::test::backend_param_name)
