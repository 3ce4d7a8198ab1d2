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
    std::size_t index = 0;  // row-major, the last axis fastest (sweep_cell)
    for (std::size_t i = 0; i < axes.size(); ++i) index = index * axes[i].values.size() + c.index[i];
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
  MergedSweep out;
  std::size_t total = 0;
  std::string first_dir, given;
  std::map<std::size_t, std::string> owner;  // cell -> the directory that holds it
  std::vector<SweepCell> cells;
  for (const std::string& dir : dirs) {
    const std::string path = dir + "/shard.json";
    std::ifstream in(path);
    if (!in) return make_error(path + ": cannot read (not a directory written by tune --shard?)");
    nlohmann::json doc;
    try {
      in >> doc;
      if (doc.at("format") != kFormat || doc.at("version") != kVersion)
        return make_error(path + ": not a sweep shard of this version (format " + doc.at("format").dump() + ")");
      std::vector<SweepAxis> axes;
      for (const auto& a : doc.at("axes")) axes.push_back({a.at("key").get<std::string>(), a.at("values").get<std::vector<std::string>>()});
      const auto n = json_int<std::size_t>(doc.at("cells_total"), "cells_total");
      given += (given.empty() ? "" : ", ") + doc.at("shard").at(0).dump() + "/" + doc.at("shard").at(1).dump();
      if (first_dir.empty()) {
        out.axes = axes;
        total = n;
        first_dir = dir;
      } else if (axes_json(axes) != axes_json(out.axes) || n != total) {
        return make_error(path + ": a shard of another sweep than " + first_dir + " (its axes or cell count differ)");
      }
      for (const auto& c : doc.at("cells")) {
        const auto index = json_int<std::size_t>(c.at("index"), "index");
        if (index >= total) return make_error(path + ": cell " + std::to_string(index) + " is outside the sweep's " + std::to_string(total) + " cells");
        if (auto [it, fresh] = owner.emplace(index, dir); !fresh)
          return make_error(path + ": cell " + std::to_string(index) + " (" + c.at("label").get<std::string>() +
                            ") is also in " + it->second + ": give each shard once");
        SweepCell cell;
        cell.index = sweep_cell(out.axes, index);
        cell.label = c.at("label").get<std::string>();
        cell.stats.shadow_pixels = json_int<std::uint32_t>(c.at("shadow_pixels"), "shadow_pixels");
        cell.stats.penetrating_pixels = json_int<std::uint32_t>(c.at("penetrating_pixels"), "penetrating_pixels");
        cell.stats.max_penetration_mm = c.at("max_penetration_mm").get<double>();
        cell.stats.speed_gain = c.at("speed_gain").get<double>();
        cell.frame_ms = c.at("frame_ms").get<double>();
        auto image = read_image(dir + "/" + c.at("image").get<std::string>());
        if (!image) return image.error();
        cell.image = std::move(image.value());
        cells.push_back(std::move(cell));
      }
    } catch (const std::exception& e) {  // nlohmann's, and json_int's range errors
      return make_error(path + ": damaged shard manifest: " + e.what());
    }
  }
  for (std::size_t i = 0; i < total; ++i)
    if (!owner.count(i))
      return make_error("--merge: cell " + std::to_string(i) + " (" + sweep_label(out.axes, sweep_cell(out.axes, i)) +
                        ") is in no shard given (" + given + "): merge all N shards");
  out.cells.resize(total);
  for (SweepCell& c : cells) {
    std::size_t index = 0;
    for (std::size_t i = 0; i < out.axes.size(); ++i) index = index * out.axes[i].values.size() + c.index[i];
    out.cells[index] = std::move(c);
  }
  return out;
}

}  // namespace ps
