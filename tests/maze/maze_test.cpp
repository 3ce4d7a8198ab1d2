// The maze (src/maze, docs/maze.md) without GL: the description's errors, the route drawn from
// the seed, the generated scenes, and whole scripted sessions through the haptic loop: every
// route is reachable, a wrong exit is scored wrong, the session ends at the first perfect pass.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "devices/sample_log.h"
#include "haptics/haptic_loop.h"
#include "maze/maze.h"
#include "maze/maze_script.h"
#include "maze/maze_session.h"
#include "maze_test_util.h"

namespace ps::maze {
namespace {

using test::maze_file;
using test::read_lines;
using test::temp_dir;

TEST(MazeDescTest, ShippedDescriptionLoads) {
  auto d = load_maze_desc(maze_file());
  ASSERT_TRUE(d) << d.error().message;
  EXPECT_EQ(d->room_size_mm, 120.0);
  EXPECT_EQ(d->viscosity_n_s_per_mm, 0.004);
  EXPECT_EQ(d->external_fluctuation_n, glm::dvec3(1.0, 0.0, 0.0));
}

// The live window's first screen: the default text, or the description's [instructions] text.
TEST(MazeDescTest, InstructionsComeFromTheDescriptionOrTheDefault) {
  auto d = parse_maze_desc("[maze]\nmax_passes = 3\n", "m.toml");
  ASSERT_TRUE(d) << d.error().message;
  EXPECT_EQ(d->instructions, kDefaultInstructions);
  auto own = parse_maze_desc("[instructions]\ntext = \"Steer with the mouse.\\nPress Space.\"\n", "m.toml");
  ASSERT_TRUE(own) << own.error().message;
  EXPECT_EQ(own->instructions, "Steer with the mouse.\nPress Space.");
  auto bad = parse_maze_desc("[instructions]\ntxt = \"x\"\n", "m.toml");
  ASSERT_FALSE(bad);
  EXPECT_EQ(bad.error().message, "m.toml:2: unknown key 'txt' in [instructions]; known keys: text");
  auto empty = parse_maze_desc("[instructions]\ntext = \"\"\n", "m.toml");
  ASSERT_FALSE(empty);
  EXPECT_EQ(empty.error().message.rfind("m.toml:2: 'text' must be a non-empty string", 0), 0u) << empty.error().message;
}

TEST(MazeDescTest, ErrorsNameTheLineAndTheFix) {
  auto unknown = parse_maze_desc("[maze]\nroom_size_mm = 100\nroom_sise_mm = 3\n", "m.toml");
  ASSERT_FALSE(unknown);
  EXPECT_EQ(unknown.error().message.rfind("m.toml:3: unknown key 'room_sise_mm' in [maze]", 0), 0u) << unknown.error().message;
  auto range = parse_maze_desc("[cues.viscosity]\nviscosity_n_s_per_mm = 3\n", "m.toml");
  ASSERT_FALSE(range);
  EXPECT_NE(range.error().message.find("m.toml:2: 'viscosity_n_s_per_mm' must be in [0, 1] (got 3)"), std::string::npos)
      << range.error().message;
  auto narrow = parse_maze_desc("[maze]\ncorridor_width_mm = 12\n", "m.toml");
  ASSERT_FALSE(narrow);
  EXPECT_NE(narrow.error().message.find("probe's diameter"), std::string::npos) << narrow.error().message;
  auto cue = parse_maze_desc("[cues.smell]\nx = 1\n", "m.toml");
  ASSERT_FALSE(cue);
  EXPECT_NE(cue.error().message.find("unknown table [cues.smell]"), std::string::npos) << cue.error().message;
}

// Same seed, same route and orders; 200 seeds give (nearly) all different routes, every exit
// is correct for some room, and every cue room comes in every place of a pass.
TEST(MazeRouteTest, SameSeedSameRouteDifferentSeedsDiffer) {
  const Route a = draw_route(42), b = draw_route(42);
  EXPECT_EQ(a.correct, b.correct);
  for (int p = 0; p < 5; ++p) EXPECT_EQ(a.order(p), b.order(p));
  std::set<std::string> routes;
  std::array<std::array<int, 6>, 6> place_count{};
  std::array<int, 3> exit_count{};
  for (std::uint64_t seed = 0; seed < 200; ++seed) {
    const Route r = draw_route(seed);
    std::string key;
    for (const Exit e : r.correct) key += exit_name(e), exit_count[static_cast<std::size_t>(e)]++;
    for (const Cue c : r.order(0)) key += cue_name(c);
    routes.insert(key);
    const auto order = r.order(0);
    EXPECT_EQ(order[0], Cue::kNone) << "the dummy room always comes first";
    for (std::size_t i = 0; i < order.size(); ++i) place_count[static_cast<std::size_t>(order[i])][i]++;
    EXPECT_NE(r.order(0), r.order(1)) << "seed " << seed << ": a new order every pass (both orders equal by chance: 1 in 120)";
  }
  // 3^6 x 120 = 87480 routes: 200 draws collide with probability ~0.2; allow 2.
  EXPECT_GE(routes.size(), 198u);
  for (const int n : exit_count) EXPECT_GT(n, 300);  // 1200 draws, ~400 each
  for (const Cue c : kCueRooms)
    for (std::size_t i = 1; i < 6; ++i) EXPECT_GT(place_count[static_cast<std::size_t>(c)][i], 15) << cue_name(c) << " at " << i;
  EXPECT_FALSE(draw_route(1).correct == draw_route(2).correct && draw_route(1).order(0) == draw_route(2).order(0));
}

// The scene of a pass: six rooms of identical shape; the cues only with cues on; the hidden
// sphere not drawn; the previous pass's last room at the start of the next pass's scene.
TEST(MazeSceneTest, RoomsAreIdenticalAndCuesFollowTheCondition) {
  auto d = load_maze_desc(maze_file());
  ASSERT_TRUE(d) << d.error().message;
  const Route route = draw_route(7);
  auto on = generate_scene(d.value(), route, true, 0);
  ASSERT_TRUE(on) << on.error().message;
  auto off = generate_scene(d.value(), route, false, 0);
  ASSERT_TRUE(off) << off.error().message;
  EXPECT_EQ(on->scene.fields.size(), 2u);  // viscosity and external force
  EXPECT_TRUE(off->scene.fields.empty());
  EXPECT_EQ(on->scene.surfaces.size(), off->scene.surfaces.size() + 1);  // + the hidden sphere
  int hidden = 0;
  for (std::size_t i = 0; i < on->scene.surfaces.size(); ++i)
    if (on->kinds[i] == SurfaceKind::kHidden) {
      ++hidden;
      EXPECT_FALSE(on->scene.surfaces[i].visible);
      EXPECT_TRUE(on->scene.surfaces[i].touchable);
    }
  EXPECT_EQ(hidden, 1);
  for (const Material& m : off->scene.materials) EXPECT_EQ(m.name, "wall") << "cues off: every room is the dummy";
  // Identical shape: room k's boxes are room 0's moved by k pitches.
  const RoomGeometry g = room_geometry(d.value());
  std::vector<std::vector<glm::dvec3>> boxes(6);
  for (std::size_t i = 0; i < on->scene.surfaces.size(); ++i)
    if (on->slots[i] >= 0 && on->scene.surfaces[i].type == SurfaceType::kBox)
      boxes[static_cast<std::size_t>(on->slots[i])].push_back(on->scene.surfaces[i].center -
                                                               glm::dvec3(0.0, g.center_y(on->slots[i]), 0.0));
  boxes[5].pop_back();  // the cap closing the maze after the last room
  for (int k = 1; k < 6; ++k) EXPECT_EQ(boxes[static_cast<std::size_t>(k)], boxes[0]) << "room " << k;
  auto pass2 = generate_scene(d.value(), route, true, 1);
  ASSERT_TRUE(pass2) << pass2.error().message;
  EXPECT_EQ(pass2->slots.front(), 5) << "pass 2's scene starts with pass 1's last room";
  // ... whose entrance (into pass 1's rooms, not in this scene) is closed: a probe walked back
  // through it stops at the south wall's line instead of leaving the maze.
  auto back = build_haptic(pass2.value());
  ASSERT_TRUE(back) << back.error().message;
  const double south = g.center_y(5) - g.a;
  const world::Contact c = back.value()->closest(glm::dvec3(0.0, south + 1.0, 7.0), 10.0);
  ASSERT_TRUE(c.hit);
  EXPECT_NEAR(c.distance_mm, 1.0, 1e-9);
}

// The walls' low friction (the description's [walls]): a device pushed diagonally 15 mm into
// the learning room's west wall, beside its door, slides the proxy along the wall after it
// (it follows the device's y to within 2 mm; with the scene parser's default friction, 0.3, the
// proxy sticks where it first touched, 5 mm behind).
TEST(MazeSceneTest, WallsLetTheProbeSlide) {
  auto d = load_maze_desc(maze_file());
  ASSERT_TRUE(d) << d.error().message;
  auto run = [&](double mu) {
    MazeDesc desc = d.value();
    desc.wall_static_friction = desc.wall_dynamic_friction = mu;
    auto scene = generate_scene(desc, draw_route(3), false, 0);
    EXPECT_TRUE(scene) << scene.error().message;
    auto haptic = build_haptic(scene.value()).value();
    const double z = desc.probe_radius_mm + 1.0;
    LogDevice dev({{0.0, {0, -40, z}, 0u, true}, {1.0, {-75, -20, z}, 0u, true}}, true, "diagonal");
    FakeClock clock;
    HapticLoop loop(dev, clock, HapticLoopParams{}, haptic.get());
    loop.run_ticks(1001);
    const HapticState st = loop.state().read();
    EXPECT_TRUE(st.in_contact);
    return st.proxy_mm.y - st.device_mm.y;
  };
  EXPECT_GT(run(0.05), -2.0);
  EXPECT_LT(run(0.3), -4.0);
}

// The live window's clutch (docs/maze.md, "A hand a wall has stopped"): a hand thrown 30 mm
// left into the start corridor's wall (the proxy stops at x = -12, 18 mm half-width less the
// 6 mm probe) is put back under the probe 100 ms later. The device's jump back is no motion of
// the person's, and its samples say so (DeviceSample::placements, as GlfwInputDevice::place
// counts it): the haptic loop restarts its filter there and the proxy stays at the wall (within
// 0.05 mm: it rests on the wall within the god-object's tolerance). The same jump without the
// count, as a person's motion, the filter carries the proxy off the wall to the right (more
// than 2 mm: the window then saw 7.5 mm and clutched a second time, there).
TEST(MazeSceneTest, AClutchRestartsTheFilterSoTheProbeStaysAtTheWall) {
  auto d = load_maze_desc(maze_file());
  ASSERT_TRUE(d) << d.error().message;
  auto scene = generate_scene(d.value(), draw_route(3), false, 0);
  ASSERT_TRUE(scene) << scene.error().message;
  auto haptic = build_haptic(scene.value()).value();
  const double z = d.value().probe_radius_mm + 1.0;
  const double wall_x = -(18.0 - d.value().probe_radius_mm);
  auto run = [&](bool counted) {
    // The mouse as the window polls it: a sample a frame (16 ms), held in between; the clutch
    // at 0.6 s puts the hand back at the wall.
    std::vector<DeviceSample> polls;
    for (int f = 0; f * 0.016 < 2.0; ++f) {
      const double t = f * 0.016;
      DeviceSample s{t, {t < 0.5 ? 0.0 : t < 0.6 ? -30.0 : wall_x, -91, z}, 0u, true};
      s.placements = counted && t >= 0.6 ? 1u : 0u;
      polls.push_back(s);
    }
    LogDevice dev(polls, false, "thrown at the wall, put back");
    FakeClock clock;
    HapticLoop loop(dev, clock, HapticLoopParams{}, haptic.get());
    loop.run_ticks(600);  // to 0.599 s: the hand thrown, the wall holding the probe
    EXPECT_NEAR(loop.state().read().proxy_mm.x, wall_x, 0.05) << "the wall holds the probe";
    double right_most = -1e9;
    for (int i = 0; i < 1000; ++i) {
      loop.run_ticks(1);
      right_most = std::max(right_most, loop.state().read().proxy_mm.x);
    }
    const HapticState st = loop.state().read();
    EXPECT_NEAR(st.device_mm.x, wall_x, 1e-12);
    EXPECT_NEAR(st.proxy_mm.x, wall_x, 0.05) << "at rest under the hand in the end";
    return right_most - wall_x;
  };
  const double counted = run(true), as_motion = run(false);
  std::printf("the proxy's largest step off the wall after the clutch: %.4f mm as a placement, %.4f mm as a motion\n",
              counted, as_motion);
  EXPECT_LT(counted, 0.05);
  EXPECT_GT(as_motion, 2.0);
}

// A scripted participant that takes `passes` exits, through a whole session.
Result<SessionResult> scripted_session(const std::string& dir, const MazeDesc& d, const Route& route, bool cues,
                                       const std::vector<PassChoices>& passes) {
  std::filesystem::create_directories(dir);
  const std::string traj = dir + "/p.traj";
  std::ofstream(traj) << script_trajectory(d, passes, 150.0);
  auto dev = open_log_device("trajectory:" + traj);
  if (!dev) return dev.error();
  SessionOptions o;
  o.desc = d;
  o.route = route;
  o.info.participant = "T";
  o.info.cues = cues;
  o.info.seed = route.seed;
  o.log_path = dir + "/session.jsonl";
  return run_session(*dev.value(), o, nullptr, nullptr);
}

// The window drains the loop's tick feed once per frame and feeds the tracker every tick
// (SessionCore::step(TickSample)): with frames 0.5 s apart - longer than the 0.2-0.6 s the
// scripted participant spends in a room at 300 mm/s, so a tracker fed one state per frame missed
// rooms and ended "after 0 passes (device_ended)" - the session scores as the headless one,
// which steps every tick: the same exits, the same pass-1 times to the tick.
TEST(MazeSessionTest, TickFeedDrainedAtSlowFramesScoresLikeEveryTick) {
  auto d = load_maze_desc(maze_file());
  ASSERT_TRUE(d) << d.error().message;
  const Route route = draw_route(5);
  const std::string dir = temp_dir("slow_frames");
  std::ofstream(dir + "/p.traj") << script_trajectory(d.value(), {choices_with_errors(route, 0, 2), correct_choices(route, 1)}, 300.0);
  SessionOptions o;
  o.desc = d.value();
  o.route = route;
  o.info.participant = "T";
  o.info.seed = route.seed;
  o.log_path = dir + "/every_tick.jsonl";
  auto every = open_log_device("trajectory:" + dir + "/p.traj");
  ASSERT_TRUE(every);
  auto reference = run_session(*every.value(), o, nullptr, nullptr);
  ASSERT_TRUE(reference) << reference.error().message;
  ASSERT_EQ(reference->reason, EndReason::kCriterion);

  o.log_path = dir + "/slow_frames.jsonl";
  auto dev = open_log_device("trajectory:" + dir + "/p.traj");
  ASSERT_TRUE(dev);
  auto core = SessionCore::open(o);
  ASSERT_TRUE(core) << core.error().message;
  FakeClock clock;
  HapticLoop loop(*dev.value(), clock, o.haptics, core.value()->haptic().get());
  TickFeed feed(1 << 12);
  loop.add_tick_feed(&feed);
  const double end_s = dev.value()->duration_s();
  for (int frame = 0; !core.value()->finished() && frame * 0.5 < end_s; ++frame) {
    loop.run_ticks(500);  // one slow frame
    Status stepped = ok_status();
    feed.drain([&](const TickSample& t) {
      if (stepped && !core.value()->finished()) stepped = core.value()->step(t, loop, nullptr);
    });
    ASSERT_TRUE(stepped) << stepped.error().message;
  }
  auto slow = core.value()->finish(core.value()->end_time_s(), EndReason::kDeviceEnded);
  ASSERT_TRUE(slow) << slow.error().message;
  EXPECT_EQ(slow->reason, EndReason::kCriterion);
  EXPECT_EQ(slow->trials_to_criterion, reference->trials_to_criterion);
  ASSERT_EQ(slow->scores.size(), reference->scores.size());
  for (std::size_t p = 0; p < slow->scores.size(); ++p)
    for (std::size_t i = 0; i < slow->scores[p].trials.size(); ++i) {
      const Trial &a = slow->scores[p].trials[i], &b = reference->scores[p].trials[i];
      EXPECT_EQ(a.chosen, b.chosen) << "pass " << p << " room " << i;
      EXPECT_EQ(a.ok, b.ok) << "pass " << p << " room " << i;
      // Pass 1 runs on the same scene tick for tick: the same times exactly. (The next pass's
      // scene reaches the loop up to a frame later than in the headless run.)
      if (p == 0) {
        EXPECT_EQ(a.enter_s, b.enter_s) << "room " << i;
        EXPECT_EQ(a.exit_s, b.exit_s) << "room " << i;
      }
    }
  EXPECT_EQ(feed.dropped(), 0u);
}

// Every seed's route can be walked: the correct exits of pass 1 finish the session with the
// criterion after one pass, every room scored right, with cues on and off.
TEST(MazeSessionTest, EveryRouteIsReachable) {
  auto d = load_maze_desc(maze_file());
  ASSERT_TRUE(d) << d.error().message;
  for (const std::uint64_t seed : {1ull, 2ull, 3ull, 99ull})
    for (const bool cues : {true, false}) {
      const Route route = draw_route(seed);
      auto r = scripted_session(temp_dir("reachable_" + std::to_string(seed) + (cues ? "_on" : "_off")), d.value(),
                                route, cues, {correct_choices(route, 0)});
      ASSERT_TRUE(r) << r.error().message;
      EXPECT_EQ(r->reason, EndReason::kCriterion) << "seed " << seed << " cues " << cues;
      ASSERT_EQ(r->scores.size(), 1u);
      for (const Trial& t : r->scores[0].trials) EXPECT_TRUE(t.ok) << cue_name(t.cue) << " took " << exit_name(t.chosen);
    }
}

// Two wrong rooms in pass 1, all right in pass 2: pass 1 scores 4 of 6 with exactly those two
// wrong, the session goes on and ends with the criterion after pass 2; the log says the same.
TEST(MazeSessionTest, WrongExitIsAFailedTrialAndThePerfectPassEnds) {
  auto d = load_maze_desc(maze_file());
  ASSERT_TRUE(d) << d.error().message;
  const Route route = draw_route(5);
  const std::string dir = temp_dir("wrong_then_right");
  auto r = scripted_session(dir, d.value(), route, true, {choices_with_errors(route, 0, 2), correct_choices(route, 1)});
  ASSERT_TRUE(r) << r.error().message;
  EXPECT_EQ(r->reason, EndReason::kCriterion);
  EXPECT_EQ(r->trials_to_criterion, 2);
  ASSERT_EQ(r->scores.size(), 2u);
  EXPECT_EQ(r->scores[0].correct(), 4);
  for (int i = 0; i < 6; ++i) EXPECT_EQ(r->scores[0].trials[static_cast<std::size_t>(i)].ok, i < 1 || i > 2) << i;
  EXPECT_EQ(r->scores[1].correct(), 6);
  const auto lines = read_lines(dir + "/session.jsonl");
  int branches = 0, wrong = 0;
  for (const std::string& l : lines) {
    const auto j = nlohmann::json::parse(l);
    if (j["type"] == "branch") ++branches, wrong += j["correct"] ? 0 : 1;
  }
  EXPECT_EQ(branches, 12);
  EXPECT_EQ(wrong, 2);
  EXPECT_EQ(nlohmann::json::parse(lines.back())["type"], "session_end");
  EXPECT_EQ(nlohmann::json::parse(lines.back())["trials_to_criterion"], 2);
}

// A second session into the same directory is refused before anything is written: the first
// participant's log stays as it was.
TEST(MazeSessionTest, AnExistingLogIsNeverOverwritten) {
  auto d = load_maze_desc(maze_file());
  ASSERT_TRUE(d) << d.error().message;
  const Route route = draw_route(5);
  const std::string dir = temp_dir("no_overwrite");
  ASSERT_TRUE(scripted_session(dir, d.value(), route, true, {correct_choices(route, 0)}));
  const auto before = read_lines(dir + "/session.jsonl");
  auto again = scripted_session(dir, d.value(), route, false, {correct_choices(route, 0)});
  ASSERT_FALSE(again);
  EXPECT_NE(again.error().message.find("a session log is already there"), std::string::npos) << again.error().message;
  EXPECT_EQ(read_lines(dir + "/session.jsonl"), before);
}

// max_passes stops a session that never gets a perfect pass.
TEST(MazeSessionTest, MaxPassesEndsASessionWithoutCriterion) {
  auto d = load_maze_desc(maze_file());
  ASSERT_TRUE(d) << d.error().message;
  d->max_passes = 2;
  const Route route = draw_route(11);
  auto r = scripted_session(temp_dir("max_passes"), d.value(), route, false,
                            {choices_with_errors(route, 0, 1), choices_with_errors(route, 1, 1), correct_choices(route, 2)});
  ASSERT_TRUE(r) << r.error().message;
  EXPECT_EQ(r->reason, EndReason::kMaxPasses);
  EXPECT_EQ(r->passes, 2);
  EXPECT_EQ(r->trials_to_criterion, 0);
}

}  // namespace
}  // namespace ps::maze
