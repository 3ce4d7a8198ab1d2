#include "gl/timer_query.h"

#include <cassert>

namespace ps::gl {

TimerQueries::~TimerQueries() {
  for (Slot& s : slots_)
    if (!s.queries.empty()) glDeleteQueries(static_cast<GLsizei>(s.queries.size()), s.queries.data());
}

void TimerQueries::start_query() {
  Slot& s = slots_[current_];
  if (s.names.size() == s.queries.size()) {
    GLuint q = 0;
    glGenQueries(1, &q);
    s.queries.push_back(q);
  }
  glBeginQuery(GL_TIME_ELAPSED, s.queries[s.names.size()]);
  open_ = true;
}

void TimerQueries::begin_frame() {
  assert(!open_ && "TimerQueries::begin_frame: end_frame() the previous frame first");
  current_ ^= 1;
  ++frame_;
  collect(slots_[current_ ^ 1], false);  // the previous frame, if the GPU is done with it
  Slot& s = slots_[current_];
  // Still pending two frames on: dropped. Reusing the queries restarts them, without a wait.
  s.pending = false;
  s.names.clear();
  s.frame = frame_;
  start_query();
}

void TimerQueries::lap(const char* name) {
  if (!open_) return;
  glEndQuery(GL_TIME_ELAPSED);
  slots_[current_].names.emplace_back(name);
  start_query();
}

void TimerQueries::end_frame() {
  if (!open_) return;
  glEndQuery(GL_TIME_ELAPSED);  // the stretch after the last lap: not a pass, never read
  open_ = false;
  slots_[current_].pending = true;
  collect(slots_[current_], false);
}

void TimerQueries::poll(bool wait) {
  collect(slots_[current_ ^ 1], false);
  collect(slots_[current_], wait);
}

bool TimerQueries::collect(Slot& slot, bool wait) {
  if (!slot.pending || slot.names.empty()) return false;
  // Queries complete in order: when the last named one is there, so are the others.
  if (!wait) {
    GLint available = GL_FALSE;
    glGetQueryObjectiv(slot.queries[slot.names.size() - 1], GL_QUERY_RESULT_AVAILABLE, &available);
    if (available == GL_FALSE) return false;
  }
  Timings t;
  t.reserve(slot.names.size());
  for (std::size_t i = 0; i < slot.names.size(); ++i) {
    GLuint64 ns = 0;
    glGetQueryObjectui64v(slot.queries[i], GL_QUERY_RESULT, &ns);
    t.emplace_back(slot.names[i], static_cast<double>(ns) * 1e-6);
  }
  slot.pending = false;
  results_ = std::move(t);
  results_frame_ = slot.frame;
  return true;
}

}  // namespace ps::gl
