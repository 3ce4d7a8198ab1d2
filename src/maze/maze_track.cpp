#include "maze/maze_track.h"

#include <algorithm>
#include <cmath>

namespace ps::maze {

int PassScore::correct() const {
  return static_cast<int>(std::count_if(trials.begin(), trials.end(), [](const Trial& t) { return t.ok; }));
}

Tracker::Tracker(const MazeDesc& desc, const Route& route, int max_passes)
    : g_(room_geometry(desc)), route_(route), max_passes_(std::max(1, max_passes)), order_(route.order(0)) {
  current_.order = order_;
}

// The probe's centre inside the current room's interior (the walls keep it R inside, so the
// interior's own bounds are where it crosses a door).
bool Tracker::inside(const glm::dvec3& p) const {
  const double y = g_.center_y(pass_ * kRoomsPerPass + index_);
  return std::abs(p.x) < g_.a && std::abs(p.y - y) < g_.a;
}

void Tracker::accumulate(const ProbeStep& s, double dt) {
  if (have_last_) trial_.path_mm += glm::length(s.proxy_mm - last_.proxy_mm);
  if (s.contact_kind >= 0 && s.contact_kind < 4) {
    if (!have_last_ || last_.contact_kind != s.contact_kind) ++trial_.contacts[static_cast<std::size_t>(s.contact_kind)];
    trial_.contact_s[static_cast<std::size_t>(s.contact_kind)] += dt;
  }
  const double f = glm::length(s.force_n);
  force_sum_ += f;
  ++force_n_;
  trial_.force_max_n = std::max(trial_.force_max_n, f);
  trial_.field_force_max_n = std::max(trial_.field_force_max_n, glm::length(s.field_force_n));
}

void Tracker::start_trial(const ProbeStep& s, std::vector<TrackEvent>& events) {
  entered_ = true;
  trial_ = Trial{};
  trial_.pass = pass_;
  trial_.index = index_;
  trial_.cue = room();
  trial_.correct = route_.correct_exit(trial_.cue);
  trial_.enter_s = s.time_s;
  force_sum_ = 0.0;
  force_n_ = 0;
  if (index_ == 0) current_.start_s = s.time_s;
  events.push_back({TrackEvent::Kind::kRoomEntered, trial_, {}, false});
}

// The probe has left the interior through a door: the branch is the side it crossed (at a
// corner, the side it is farther past). Then the next room, or the pass's end.
void Tracker::end_trial(const ProbeStep& s, std::vector<TrackEvent>& events) {
  const double y = g_.center_y(pass_ * kRoomsPerPass + index_);
  const glm::dvec3 p = s.proxy_mm;
  const double past_x = std::abs(p.x) - g_.a, past_y = p.y - y - g_.a;
  trial_.chosen = past_y >= past_x ? Exit::kStraight : p.x < 0.0 ? Exit::kLeft : Exit::kRight;
  trial_.ok = trial_.chosen == trial_.correct;
  trial_.exit_s = s.time_s;
  trial_.force_mean_n = force_n_ > 0 ? force_sum_ / static_cast<double>(force_n_) : 0.0;
  current_.trials.push_back(trial_);
  events.push_back({TrackEvent::Kind::kBranch, trial_, {}, false});
  entered_ = false;
  if (++index_ < kRoomsPerPass) return;
  end_pass(s.time_s, events);
}

void Tracker::end_pass(double time_s, std::vector<TrackEvent>& events) {
  current_.pass = pass_;
  current_.end_s = time_s;
  done_.push_back(current_);
  events.push_back({TrackEvent::Kind::kPassEnd, {}, current_, false});
  const bool criterion = current_.correct() == kRoomsPerPass;
  if (criterion || pass_ + 1 >= max_passes_) {
    finished_ = true;
    index_ = kRoomsPerPass - 1;  // room() stays on the last room
    events.push_back({TrackEvent::Kind::kFinished, {}, {}, criterion});
    return;
  }
  ++pass_;
  index_ = 0;
  order_ = route_.order(pass_);
  current_ = PassScore{};
  current_.order = order_;
}

std::vector<TrackEvent> Tracker::resume(const std::vector<PassScore>& done, const PassScore& current) {
  done_ = done;
  pass_ = current.pass;
  order_ = route_.order(pass_);
  current_ = current;
  current_.order = order_;
  index_ = static_cast<int>(current.trials.size());
  entered_ = false;
  have_last_ = false;
  std::vector<TrackEvent> events;
  if (index_ >= kRoomsPerPass) end_pass(current.trials.back().exit_s, events);
  return events;
}

std::vector<TrackEvent> Tracker::feed(const ProbeStep& s) {
  std::vector<TrackEvent> events;
  if (finished_) return events;
  const double dt = have_last_ ? std::max(0.0, s.time_s - last_.time_s) : 0.0;
  const bool in = inside(s.proxy_mm);
  if (!entered_ && in) start_trial(s, events);  // first tick in the room: the trial starts
  if (entered_) accumulate(s, dt);
  last_ = s;
  have_last_ = true;
  if (!entered_ || in) return events;
  const double y = g_.center_y(pass_ * kRoomsPerPass + index_);
  if (s.proxy_mm.y - y <= -g_.a && std::abs(s.proxy_mm.x) < g_.a) return events;  // back out of the entrance: no choice
  end_trial(s, events);
  return events;
}

}  // namespace ps::maze
