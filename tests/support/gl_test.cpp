#include "support/gl_test.h"

namespace ps::test {

void GlTest::SetUp() {
  ps::gl::ContextDesc desc;
  desc.backend = GetParam();
  auto context = ps::gl::create_context(desc);
  // ASSERT in SetUp stops the test body from running without a context.
  ASSERT_TRUE(context.ok()) << context.error().message;
  context_ = std::move(context.value());
}

void GlTest::TearDown() { context_.reset(); }

bool is_llvmpipe(const ps::gl::Context& context) {
  return context.renderer().find("llvmpipe") != std::string::npos;
}

std::string backend_param_name(const ::testing::TestParamInfo<ps::gl::Backend>& info) {
  return ps::gl::backend_name(info.param);
}

}  // namespace ps::test
