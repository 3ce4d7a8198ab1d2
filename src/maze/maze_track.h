// Branch detection and scoring from the probe's path (Sepulveda-Cervantes et al. §VI items 3-4):
// which exit the probe (the haptic proxy: the avatar the participant steers) leaves each room by,
// the trial's numbers (time, path length, contacts and contact time per surface kind, forces), the
// score of each pass, and the end of the session when a pass has every room right. No GL, no I/O.
#pragma once

#include <array>
#include <vector>

#include "maze/maze.h"

namespace ps::maze {

// One room of one pass.
struct Trial {
  int pass = 0;          // from 0
  int index = 0;         // the room's place in the pass, 0..5 (0: the dummy room)
  Cue cue = Cue::kNone;
  Exit chosen = Exit::kStraight;
  Exit correct = Exit::kStraight;
  bool ok = false;
  double enter_s = 0.0, exit_s = 0.0;  // session time the probe entered the room and left it
  double path_mm = 0.0;                // the probe's path inside the room
  std::array<int, 4> contacts{};       // contacts begun, per SurfaceKind (floor, wall, ceiling, hidden)
  std::array<double, 4> contact_s{};   // time in contact, per SurfaceKind
  double force_mean_n = 0.0, force_max_n = 0.0;  // |F| sent to the device while in the room
  double field_force_max_n = 0.0;                // |fields| on the probe (viscosity, external force)
  double time_s() const { return exit_s - enter_s; }
};

struct PassScore {
  int pass = 0;
  std::array<Cue, kRoomsPerPass> order{};
  std::vector<Trial> trials;  // in room order
  int correct() const;
  double start_s = 0.0, end_s = 0.0;  // first room entered, last room left
};

// What one tick of the probe is, for the tracker.
struct ProbeStep {
  double time_s = 0.0;
  glm::dvec3 proxy_mm{0.0};
  glm::dvec3 force_n{0.0};
  glm::dvec3 field_force_n{0.0};
  int contact_kind = -1;  // SurfaceKind of the touched surface, -1: none
};

struct TrackEvent {
  enum class Kind { kRoomEntered, kBranch, kPassEnd, kFinished };
  Kind kind = Kind::kRoomEntered;
  Trial trial;      // kRoomEntered (enter fields only), kBranch
  PassScore score;  // kPassEnd
  bool criterion = false;  // kFinished: true when a pass had every room right (else max_passes)
};

class Tracker {
 public:
  Tracker(const MazeDesc& desc, const Route& route, int max_passes);
  // Feeds one tick; returns what happened at it (usually nothing).
  std::vector<TrackEvent> feed(const ProbeStep& s);
  int pass() const { return pass_; }
  int index() const { return index_; }      // the room the probe is in or heading to
  Cue room() const { return order_[static_cast<std::size_t>(index_)]; }
  bool finished() const { return finished_; }
  const std::vector<PassScore>& passes() const { return done_; }
  // Continues a session read back from its log (maze_resume.h): the passes it finished and the
  // trials of the pass in progress; the next room is the next unfinished trial. When `current`
  // already holds every room (the process died between its last branch and its pass_end line),
  // the pass ends here and its events (kPassEnd, maybe kFinished) are returned; else none.
  std::vector<TrackEvent> resume(const std::vector<PassScore>& done, const PassScore& current);

 private:
  bool inside(const glm::dvec3& p) const;
  void accumulate(const ProbeStep& s, double dt);
  void start_trial(const ProbeStep& s, std::vector<TrackEvent>& events);
  void end_trial(const ProbeStep& s, std::vector<TrackEvent>& events);
  void end_pass(double time_s, std::vector<TrackEvent>& events);
  RoomGeometry g_;
  Route route_;
  int max_passes_;
  int pass_ = 0, index_ = 0;
  std::array<Cue, kRoomsPerPass> order_{};
  bool entered_ = false, finished_ = false, have_last_ = false;
  ProbeStep last_;
  Trial trial_;
  double force_sum_ = 0.0;
  long long force_n_ = 0;
  PassScore current_;
  std::vector<PassScore> done_;
};

}  // namespace ps::maze
