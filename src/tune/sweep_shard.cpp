#include "tune/sweep_shard.h"

#include <charconv>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/json_int.h"
#include "image/image.h"

namespace ps {

namespace {

constexpr const char* kFormat = "pseudoshadow-sweep-shard";
constexpr int kVersion = 1;

std::string cell_file(std::size_t index) {
  char name[32];
  std::snprintf(name, sizeof name, "cell_%04zu.png", index);
  return name;
}

bool parse_size(std::string_view s, std::size_t& out) {
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc() && end == s.data() + s.size();
}

nlohmann::json axes_json(const std::vector<SweepAxis>& axes) {
  nlohmann::json out = nlohmann::json::array();
  for (const SweepAxis& a : axes) out.push_back({{"key", a.key}, {"values", a.values}});
  return out;
}

// A cell's place in the sweep: row-major, the last axis fastest (sweep_cell).
std::size_t cell_index(const std::vector<SweepAxis>& axes, const std::vector<std::size_t>& at) {
  std::size_t index = 0;
  for (std::size_t i = 0; i < axes.size(); ++i) index = index * axes[i].values.size() + at[i];
  return index;
}

// What merge_shards() gathers, shard after shard.
struct Merge {
  MergedSweep out;
  std::size_t total = 0;
  std::string first_dir, given;
  std::map<std::size_t, std::string> owner;  // cell -> the directory that holds it
  std::vector<SweepCell> cells;
};

// A shard's sweep (axes, cell count) is the first shard's; the first one sets it. Throws
// nlohmann's and json_int's errors.
Status check_sweep(const nlohmann::json& doc, const std::string& dir, const std::string& path, Merge& m) {
  if (doc.at("format") != kFormat || doc.at("version") != kVersion)
    return make_error(path + ": not a sweep shard of this version (format " + doc.at("format").dump() + ")");
  std::vector<SweepAxis> axes;
  for (const auto& a : doc.at("axes")) axes.push_back({a.at("key").get<std::string>(), a.at("values").get<std::vector<std::string>>()});
  const auto n = json_int<std::size_t>(doc.at("cells_total"), "cells_total");
  m.given += (m.given.empty() ? "" : ", ") + doc.at("shard").at(0).dump() + "/" + doc.at("shard").at(1).dump();
  if (m.first_dir.empty()) {
    m.out.axes = axes;
    m.total = n;
    m.first_dir = dir;
  } else if (axes_json(axes) != axes_json(m.out.axes) || n != m.total) {
    return make_error(path + ": a shard of another sweep than " + m.first_dir + " (its axes or cell count differ)");
  }
  return ok_status();
}

// One cell of a shard's manifest, with its image from `dir`. Throws as check_sweep() does.
Status read_cell(const nlohmann::json& c, const std::string& dir, const std::string& path, Merge& m) {
  const auto index = json_int<std::size_t>(c.at("index"), "index");
  if (index >= m.total) return make_error(path + ": cell " + std::to_string(index) + " is outside the sweep's " + std::to_string(m.total) + " cells");
  if (auto [it, fresh] = m.owner.emplace(index, dir); !fresh)
    return make_error(path + ": cell " + std::to_string(index) + " (" + c.at("label").get<std::string>() +
                      ") is also in " + it->second + ": give each shard once");
  SweepCell cell;
  cell.index = sweep_cell(m.out.axes, index);
  cell.label = c.at("label").get<std::string>();
  cell.stats.shadow_pixels = json_int<std::uint32_t>(c.at("shadow_pixels"), "shadow_pixels");
  cell.stats.penetrating_pixels = json_int<std::uint32_t>(c.at("penetrating_pixels"), "penetrating_pixels");
  cell.stats.max_penetration_mm = c.at("max_penetration_mm").get<double>();
  cell.stats.speed_gain = c.at("speed_gain").get<double>();
  cell.frame_ms = c.at("frame_ms").get<double>();
  auto image = read_image(dir + "/" + c.at("image").get<std::string>());
  if (!image) return image.error();
  cell.image = std::move(image.value());
  m.cells.push_back(std::move(cell));
  return ok_status();
}

// One shard directory: its manifest checked against the shards before it, its cells read.
Status read_shard(const std::string& dir, Merge& m) {
  const std::string path = dir + "/shard.json";
  std::ifstream in(path);
  if (!in) return make_error(path + ": cannot read (not a directory written by tune --shard?)");
  nlohmann::json doc;
  try {
    in >> doc;
    if (Status st = check_sweep(doc, dir, path, m); !st) return st;
    for (const auto& c : doc.at("cells"))
      if (Status st = read_cell(c, dir, path, m); !st) return st;
  } catch (const std::exception& e) {  // nlohmann's, and json_int's range errors
    return make_error(path + ": damaged shard manifest: " + e.what());
  }
  return ok_status();
}

}  // namespace

Result<ShardSpec> parse_shard(std::string_view text) {
  const std::string where = "--shard " + std::string(text) + ": ";
  const std::size_t slash = text.find('/');
  ShardSpec s;
  if (slash == std::string_view::npos || !parse_size(text.substr(0, slash), s.index) ||
      !parse_size(text.substr(slash + 1), s.count))
    return make_error(where + "expected I/N, shard I of N (e.g. 2/8)");
  if (s.count < 1 || s.count > kMaxSweepCells)
    return make_error(where + "N must be in [1, " + std::to_string(kMaxSweepCells) + "]");
  if (s.index < 1 || s.index > s.count) return make_error(where + "I must be in [1, N]");
  return s;
}

Status stage_shard(OutputSet& outputs, const std::string& dir, const std::vector<SweepAxis>& axes,
                   std::size_t cells_total, const ShardSpec& shard, const std::vector<SweepCell>& cells) {
  nlohmann::json doc;
  doc["format"] = kFormat;
  doc["version"] = kVersion;
  doc["axes"] = axes_json(axes);
  doc["cells_total"] = cells_total;
  doc["shard"] = {shard.index, shard.count};
  doc["cells"] = nlohmann::json::array();
  for (const SweepCell& c : cells) {
    const std::size_t index = cell_index(axes, c.index);
    const std::string file = cell_file(index);
    if (Status s = stage_image(outputs, dir + "/" + file, c.image); !s) return s;
    doc["cells"].push_back({{"index", index},
                            {"label", c.label},
                            {"image", file},
                            {"shadow_pixels", c.stats.shadow_pixels},
                            {"penetrating_pixels", c.stats.penetrating_pixels},
                            {"max_penetration_mm", c.stats.max_penetration_mm},
                            {"speed_gain", c.stats.speed_gain},
                            {"frame_ms", c.frame_ms}});
  }
  return outputs.stage_text(dir + "/shard.json", doc.dump(1) + "\n");
}

Result<MergedSweep> merge_shards(const std::vector<std::string>& dirs) {
  if (dirs.empty()) return make_error("--merge: no shard directories given");
  Merge m;
  for (const std::string& dir : dirs)
    if (Status st = read_shard(dir, m); !st) return st.error();
  for (std::size_t i = 0; i < m.total; ++i)
    if (!m.owner.count(i))
      return make_error("--merge: cell " + std::to_string(i) + " (" + sweep_label(m.out.axes, sweep_cell(m.out.axes, i)) +
                        ") is in no shard given (" + m.given + "): merge all N shards");
  m.out.cells.resize(m.total);
  for (SweepCell& c : m.cells) m.out.cells[cell_index(m.out.axes, c.index)] = std::move(c);
  return std::move(m.out);
}

}  // namespace ps
