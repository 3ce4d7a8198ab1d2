// TimerQueries (gl/timer_query.h): per-pass GL_TIME_ELAPSED results, read without waiting.
#include <gtest/gtest.h>

#include "gl/gl.h"
#include "gl/timer_query.h"
#include "support/gl_test.h"

namespace {

class TimerQueriesGLTest : public ps::test::GlTest {};

std::vector<std::string> names(const ps::gl::TimerQueries::Timings& t) {
  std::vector<std::string> out;
  for (const auto& [name, ms] : t) out.push_back(name);
  return out;
}

TEST_P(TimerQueriesGLTest, NothingBeforeTheFirstFrame) {
  ps::gl::TimerQueries q;
  EXPECT_TRUE(q.results().empty());
  EXPECT_EQ(q.lag(), -1);
}

// One frame of two passes, then a wait (what `render` does after its last frame).
TEST_P(TimerQueriesGLTest, AFrameGivesOneTimePerPass) {
  ps::gl::TimerQueries q;
  q.begin_frame();
  q.lap("first");
  q.lap("second");
  q.end_frame();
  q.poll(true);
  ASSERT_EQ(names(q.results()), (std::vector<std::string>{"first", "second"}));
  for (const auto& [name, ms] : q.results()) EXPECT_GE(ms, 0.0) << name;
  EXPECT_EQ(q.lag(), 0);
}

// The next frame's begin reads the previous frame's results once the GL is done with them: here
// a glFinish between frames makes them ready, so they are taken there, one frame old.
TEST_P(TimerQueriesGLTest, TheNextFrameReadsThePreviousOne) {
  ps::gl::TimerQueries q;
  q.begin_frame();
  q.lap("a");
  glFinish();
  q.end_frame();  // available already after the finish: taken at once, lag 0
  EXPECT_EQ(names(q.results()), std::vector<std::string>{"a"});
  q.begin_frame();
  EXPECT_EQ(q.lag(), 1) << "frame 0's results, seen from frame 1";
  q.lap("b");
  q.lap("c");
  q.end_frame();
  q.poll(true);
  EXPECT_EQ(names(q.results()), (std::vector<std::string>{"b", "c"}));
  EXPECT_EQ(q.lag(), 0);
}

PS_INSTANTIATE_HEADLESS_BACKENDS(TimerQueriesGLTest);

}  // namespace
