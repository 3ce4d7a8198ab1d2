#include "maze/maze_script.h"

#include <cstdio>

namespace ps::maze {

PassChoices correct_choices(const Route& route, int pass) {
  PassChoices c{};
  const auto order = route.order(pass);
  for (std::size_t i = 0; i < c.size(); ++i) c[i] = route.correct_exit(order[i]);
  return c;
}

PassChoices choices_with_errors(const Route& route, int pass, int wrong) {
  PassChoices c = correct_choices(route, pass);
  for (int i = 1; i <= wrong && i < kRoomsPerPass; ++i)
    c[static_cast<std::size_t>(i)] = static_cast<Exit>((static_cast<int>(c[static_cast<std::size_t>(i)]) + 1) % 3);
  return c;
}

std::string script_trajectory(const MazeDesc& desc, const std::vector<PassChoices>& passes, double speed_mm_s,
                              double height_mm) {
  const RoomGeometry g = room_geometry(desc);
  const double z = height_mm >= 0.0 ? height_mm : desc.probe_radius_mm + 1.0, a = g.a;
  std::vector<glm::dvec2> way{glm::dvec2(g.start(desc.probe_radius_mm))};
  for (std::size_t p = 0; p < passes.size(); ++p)
    for (int i = 0; i < kRoomsPerPass; ++i) {
      const int slot = static_cast<int>(p) * kRoomsPerPass + i;
      const double y = g.center_y(slot), hall = g.hall_y(slot), cx = g.channel_x();
      way.emplace_back(0.0, y - 0.66 * a);  // in through the entrance
      switch (passes[p][static_cast<std::size_t>(i)]) {
        case Exit::kLeft:
        case Exit::kRight: {
          const double s = passes[p][static_cast<std::size_t>(i)] == Exit::kLeft ? -1.0 : 1.0;
          way.emplace_back(s * 0.66 * a, y - 0.25 * a);
          way.emplace_back(s * cx, y);           // through the side door into the channel
          way.emplace_back(s * cx, hall);        // along the channel into the hall
          break;
        }
        case Exit::kStraight:  // to the right of the hidden sphere's default place
          way.emplace_back(0.5 * a, y - 0.2 * a);
          way.emplace_back(0.25 * a, y + 0.5 * a);
          break;
      }
      way.emplace_back(0.0, hall);  // the hall's door, on to the next room
    }
  std::string out = "# time_s x_mm y_mm z_mm buttons: a scripted maze participant (pseudoshadow maze script)\n";
  double t = 0.0;
  char line[128];
  for (std::size_t k = 0; k < way.size(); ++k) {
    if (k > 0) t += glm::length(way[k] - way[k - 1]) / speed_mm_s;
    std::snprintf(line, sizeof line, "%.6f %.4f %.4f %.4f 0\n", t + 0.2, way[k].x, way[k].y, z);
    if (k == 0) {
      char first[128];
      std::snprintf(first, sizeof first, "0.0 %.4f %.4f %.4f 0\n", way[k].x, way[k].y, z);
      out += first;  // held still for 0.2 s while the filter settles
    }
    out += line;
  }
  return out;
}

}  // namespace ps::maze
