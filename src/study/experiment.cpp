// Reading an experiment file (docs/study.md, "Experiment files"). Every table's keys are listed
// with the reader that checks each; an unknown key names the known ones, a bad value says what
// is allowed, both with the file's line (the same "file:line: " form as scenes and mazes).
#include "study/experiment.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include <toml++/toml.h>

#include "core/file_io.h"
#include "scene/toml_text.h"

namespace ps::study {

const char* task_name(Task t) {
  return t == Task::kThreshold ? "threshold" : t == Task::kIdentification ? "identification" : "targeting";
}
const char* method_name(Method m) { return m == Method::kPsi ? "psi" : "staircase"; }

namespace {

// A reading error: the message is complete ("file:line: ..."); thrown inside the reader only and
// turned into an error value by parse_experiment.
struct BadFile : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class Reader {
 public:
  explicit Reader(std::string source) : source_(std::move(source)) {}
  int line(const toml::node& n) const { return std::max(1, static_cast<int>(n.source().begin.line)); }
  std::string where(int line) const { return source_ + ":" + std::to_string(line) + ": "; }
  [[noreturn]] void fail(const toml::node& n, const std::string& what) const {
    throw BadFile(source_ + ":" + std::to_string(line(n)) + ": " + what);
  }
  std::string text(const toml::node& n, const std::string& key) const {
    const auto v = n.value<std::string>();
    if (!v || v->empty()) fail(n, "'" + key + "' must be a non-empty string");
    return *v;
  }
  double number(const toml::node& n, const std::string& key, double lo, double hi) const {
    const auto v = n.value<double>();
    if (!v || !std::isfinite(*v) || *v < lo || *v > hi) {
      std::ostringstream o;
      o << "'" << key << "' must be a number in [" << lo << ", " << hi << "]";
      fail(n, o.str());
    }
    return *v;
  }
  int whole(const toml::node& n, const std::string& key, int lo, int hi) const {
    const double v = number(n, key, lo, hi);
    if (v != std::floor(v)) fail(n, "'" + key + "' must be a whole number");
    return static_cast<int>(v);
  }
  std::string choice(const toml::node& n, const std::string& key, const std::vector<std::string>& allowed) const {
    const auto v = n.value<std::string>();
    std::string list;
    for (const std::string& a : allowed) list += (list.empty() ? "\"" : ", \"") + a + "\"";
    if (!v || std::find(allowed.begin(), allowed.end(), *v) == allowed.end())
      fail(n, "'" + key + "' must be one of " + list);
    return *v;
  }
  std::vector<std::string> strings(const toml::node& n, const std::string& key) const {
    const toml::array* a = n.as_array();
    if (a == nullptr || a->empty()) fail(n, "'" + key + "' must be a non-empty array of strings, e.g. [\"1\", \"2\"]");
    std::vector<std::string> out;
    for (const toml::node& e : *a) out.push_back(text(e, key + "[]"));
    return out;
  }
  // An empty array is allowed: a condition that is the scene as it stands (a baseline).
  std::vector<Override> overrides(const toml::node& n, const std::string& key) const {
    std::vector<Override> out;
    if (const toml::array* a = n.as_array(); a != nullptr && a->empty()) return out;
    for (const std::string& s : strings(n, key)) {
      if (s.find('=') == std::string::npos || s.front() == '=')
        fail(n, "'" + key + "' holds --set-style overrides KEY=VALUE, e.g. \"materials.wood.a_max=0.5\" (got \"" + s + "\")");
      out.push_back({s, line(n)});
    }
    return out;
  }
  const toml::table& table(const toml::node& n, const std::string& name) const {
    if (n.as_table() == nullptr) fail(n, "'" + name + "' must be a table, e.g. [" + name + "]");
    return *n.as_table();
  }

  using KeyReader = std::function<void(const toml::node&)>;
  // Reads every key of `t` with its reader; an unknown key names the known ones.
  void keys(const toml::table& t, const std::string& name, const std::vector<std::pair<std::string, KeyReader>>& known) const {
    for (const auto& [key, node] : t) {
      const std::string word(key.str());  // a copy: clang before 16 cannot capture a structured binding
      const auto it = std::find_if(known.begin(), known.end(), [&](const auto& k) { return k.first == word; });
      if (it == known.end()) {
        std::string list;
        for (const auto& k : known) list += (list.empty() ? "" : ", ") + k.first;
        fail(node, "unknown key '" + word + "' in [" + name + "]; known keys: " + list);
      }
      it->second(node);
    }
  }

 private:
  std::string source_;
};

void read_experiment_table(const Reader& r, const toml::node& n, Experiment& e, int& trials_line) {
  r.keys(r.table(n, "experiment"), "experiment",
         {{"name", [&](const toml::node& v) { e.name = r.text(v, "name"); }},
          {"task", [&](const toml::node& v) {
             const std::string t = r.choice(v, "task", {"threshold", "identification", "targeting"});
             e.task = t == "threshold" ? Task::kThreshold : t == "identification" ? Task::kIdentification : Task::kTargeting;
           }},
          {"instructions", [&](const toml::node& v) { e.instructions = r.text(v, "instructions"); }},
          {"trials", [&](const toml::node& v) {
             e.trials = r.whole(v, "trials", 1, 10000);
             trials_line = r.line(v);
           }},
          {"blocks", [&](const toml::node& v) { e.blocks = r.whole(v, "blocks", 1, 100); }},
          {"practice_trials", [&](const toml::node& v) { e.practice = r.whole(v, "practice_trials", 0, 1000); }},
          {"first_seed", [&](const toml::node& v) {
             const double seed = r.number(v, "first_seed", 0, 9007199254740991.0);
             if (seed != std::floor(seed)) r.fail(v, "'first_seed' must be a whole number");
             e.first_seed = static_cast<std::uint64_t>(seed);
           }},
          {"response_keys", [&](const toml::node& v) { e.response_keys = r.strings(v, "response_keys"); }}});
}

void read_scene_table(const Reader& r, const toml::node& n, Experiment& e) {
  r.keys(r.table(n, "scene"), "scene",
         {{"path", [&](const toml::node& v) { e.scene = r.text(v, "path"); }},
          {"set", [&](const toml::node& v) { e.scene_set = r.overrides(v, "set"); }}});
}

Shape shape_of(const std::string& s) {
  return s == "logistic" ? Shape::kLogistic : s == "normal" ? Shape::kCumulativeNormal : Shape::kWeibull;
}

void read_threshold_table(const Reader& r, const toml::node& n, ThresholdSpec& t) {
  r.keys(r.table(n, "threshold"), "threshold",
         {{"method", [&](const toml::node& v) {
             t.method = r.choice(v, "method", {"psi", "staircase"}) == "psi" ? Method::kPsi : Method::kStaircase;
           }},
          {"keys", [&](const toml::node& v) { t.keys = r.strings(v, "keys"); t.keys_line = r.line(v); }},
          {"value", [&](const toml::node& v) {
             t.value = r.text(v, "value");
             if (t.value.find("{}") == std::string::npos) r.fail(v, "'value' must hold {} where the number goes, e.g. \"[0.0, 0.0, {}]\"");
           }},
          {"reference", [&](const toml::node& v) { t.reference = r.number(v, "reference", -1e6, 1e6); }},
          {"offset", [&](const toml::node& v) { t.offset = r.number(v, "offset", -1e6, 1e6); }},
          {"level_min", [&](const toml::node& v) { t.level_min = r.number(v, "level_min", 1e-9, 1e6); }},
          {"level_max", [&](const toml::node& v) { t.level_max = r.number(v, "level_max", 1e-9, 1e6); }},
          {"shape", [&](const toml::node& v) { t.shape = shape_of(r.choice(v, "shape", {"weibull", "logistic", "normal"})); }},
          {"criterion", [&](const toml::node& v) { t.criterion = r.number(v, "criterion", 0.51, 0.99); }},
          {"lapse", [&](const toml::node& v) { t.lapse = r.number(v, "lapse", 0.0, 0.1); }}});
}

// [[conditions]] or [[identification.materials]]: an array of tables of `name` and `set`.
std::vector<Variant> read_variants(const Reader& r, const toml::node& n, const std::string& name) {
  const toml::array* a = n.as_array();
  if (a == nullptr || !a->is_array_of_tables())
    r.fail(n, "'" + name + "' must be an array of tables, each [[" + name + "]] with name = \"...\" and set = [...]");
  std::vector<Variant> out;
  for (const toml::node& item : *a) {
    Variant v;
    v.line = r.line(item);
    r.keys(*item.as_table(), name,
           {{"name", [&](const toml::node& x) { v.name = r.text(x, "name"); }},
            {"set", [&](const toml::node& x) { v.set = r.overrides(x, "set"); }}});
    if (v.name.empty()) r.fail(item, "each [[" + name + "]] needs a name = \"...\"");
    for (const Variant& o : out)
      if (o.name == v.name) r.fail(item, "two [[" + name + "]] are named '" + v.name + "'");
    out.push_back(v);
  }
  return out;
}

// Numbers in [lo, hi], at least one.
std::vector<double> numbers(const Reader& r, const toml::node& n, const std::string& key, double lo, double hi) {
  const toml::array* a = n.as_array();
  if (a == nullptr || a->empty()) r.fail(n, "'" + key + "' must be an array of numbers, e.g. [40.0, 80.0]");
  std::vector<double> out;
  for (const toml::node& x : *a) out.push_back(r.number(x, key, lo, hi));
  return out;
}

std::array<double, 3> vec3(const Reader& r, const toml::node& n, const std::string& key) {
  const toml::array* a = n.as_array();
  if (a == nullptr || a->size() != 3) r.fail(n, "'" + key + "' must be [x, y, z] in mm");
  return {r.number(*a->get(0), key, -1e6, 1e6), r.number(*a->get(1), key, -1e6, 1e6), r.number(*a->get(2), key, -1e6, 1e6)};
}

void read_targeting_table(const Reader& r, const toml::node& n, TargetingSpec& t) {
  r.keys(r.table(n, "targeting"), "targeting",
         {{"distances_mm", [&](const toml::node& v) { t.distances_mm = numbers(r, v, "distances_mm", 1e-3, 1e5); }},
          {"widths_mm", [&](const toml::node& v) { t.widths_mm = numbers(r, v, "widths_mm", 1e-3, 1e5); }},
          {"targets", [&](const toml::node& v) {
             t.targets = r.whole(v, "targets", 3, 63);
             if (t.targets % 2 == 0)
               r.fail(v, "'targets' must be odd (ISO 9241-9): selecting across an even ring visits only two targets");
           }},
          {"sequences", [&](const toml::node& v) { t.sequences = r.whole(v, "sequences", 1, 100); }},
          {"centre", [&](const toml::node& v) { t.centre = vec3(r, v, "centre"); }},
          {"normal", [&](const toml::node& v) {
             t.normal = vec3(r, v, "normal");
             if (t.normal[0] == 0.0 && t.normal[1] == 0.0 && t.normal[2] == 0.0) r.fail(v, "'normal' must not be [0, 0, 0]");
           }}});
}

void read_identification_table(const Reader& r, const toml::node& n, Experiment& e) {
  r.keys(r.table(n, "identification"), "identification",
         {{"materials", [&](const toml::node& v) { e.materials = read_variants(r, v, "identification.materials"); }}});
}

// What the tables cannot say alone: the levels' order, the task's own tables and keys.
void check_whole(const Reader& r, const toml::table& root, Experiment& e, int trials_line) {
  const auto need = [&](bool ok, const std::string& what) {
    if (!ok) r.fail(root, what);
  };
  need(!e.scene.empty(), "[scene] path is missing: name the scene the stimuli are drawn from, e.g. path = \"../default.toml\"");
  if (e.task == Task::kThreshold) {
    need(root.contains("threshold"), "a threshold task needs a [threshold] table (keys, reference, level_min, level_max)");
    need(!e.threshold.keys.empty(), "[threshold] keys is missing: the scene keys it varies, e.g. [\"materials.wood.lambda_min\"]");
    need(e.threshold.level_min < e.threshold.level_max, "[threshold] level_min must be below level_max");
    if (e.response_keys.empty()) e.response_keys = {"1", "2"};
    need(e.response_keys.size() == 2, "[experiment] response_keys: a 2AFC threshold takes 2 keys (interval 1, interval 2)");
  } else if (e.task == Task::kTargeting) {
    const TargetingSpec& t = e.targeting;
    const int derived = t.sequences * static_cast<int>(t.distances_mm.size() * t.widths_mm.size()) * t.targets;
    if (trials_line > 0)
      throw BadFile(r.where(trials_line) + "a targeting task derives its trials ([targeting] sequences x distances x widths x targets = " +
                    std::to_string(derived) + "): leave 'trials' out");
    e.trials = derived;
    need(e.response_keys.empty(), "[experiment] response_keys: a targeting task is answered by touching, not by keys");
    for (const double d : t.distances_mm)
      for (const double w : t.widths_mm)
        need(w < d * std::sin(3.14159265358979323846 / t.targets),
             "[targeting] a target of width " + std::to_string(w) + " mm overlaps its neighbours on the ring of " + std::to_string(d) +
                 " mm: each W must be below D sin(pi / targets)");
  } else {
    need(e.materials.size() >= 2, "an identification task needs at least 2 [[identification.materials]]");
    if (e.response_keys.empty())
      for (std::size_t i = 1; i <= e.materials.size(); ++i) e.response_keys.push_back(std::to_string(i));
    need(e.response_keys.size() == e.materials.size(),
         "[experiment] response_keys: one key per material (" + std::to_string(e.materials.size()) + ")");
    need(e.trials % static_cast<int>(e.materials.size()) == 0,
         "[experiment] trials (" + std::to_string(e.trials) + ") must be a multiple of the " +
             std::to_string(e.materials.size()) + " materials, so that each is shown equally often");
  }
  if (e.conditions.empty()) e.conditions.push_back({"main", {}, 0});
}

}  // namespace

Result<Experiment> parse_experiment(const std::string& text, const std::string& source_name) {
  Result<toml::table> parsed = parse_toml(text, source_name);
  if (!parsed) return parsed.error();
  Experiment e;
  e.path = source_name;
  const Reader r(source_name);
  int trials_line = 0;
  try {
    r.keys(parsed.value(), "the file's top level",
           {{"experiment", [&](const toml::node& n) { read_experiment_table(r, n, e, trials_line); }},
            {"targeting", [&](const toml::node& n) { read_targeting_table(r, n, e.targeting); }},
            {"scene", [&](const toml::node& n) { read_scene_table(r, n, e); }},
            {"threshold", [&](const toml::node& n) { read_threshold_table(r, n, e.threshold); }},
            {"identification", [&](const toml::node& n) { read_identification_table(r, n, e); }},
            {"conditions", [&](const toml::node& n) { e.conditions = read_variants(r, n, "conditions"); }}});
    check_whole(r, parsed.value(), e, trials_line);
  } catch (const BadFile& bad) {
    return make_error(bad.what());
  }
  if (e.name.empty()) e.name = std::filesystem::path(source_name).stem().string();
  const std::filesystem::path scene(e.scene);
  if (scene.is_relative()) e.scene = (std::filesystem::path(source_name).parent_path() / scene).lexically_normal().string();
  return e;
}

Result<Experiment> load_experiment(const std::string& path) {
  const std::optional<std::string> text = read_whole_file(path);
  if (!text) return make_error(path + ": cannot open the experiment file (e.g. scenes/studies/lambda_threshold.toml)");
  return parse_experiment(*text, path);
}

namespace {
void append(std::vector<std::string>& out, const std::vector<Override>& set) {
  for (const Override& o : set) out.push_back(o.text);
}
}  // namespace

std::vector<std::string> threshold_overrides(const Experiment& e, const Variant& condition, double level) {
  std::vector<std::string> out;
  append(out, e.scene_set);
  append(out, condition.set);
  char number[32];  // the shortest text that reads back as the same double
  const auto end = std::to_chars(number, number + sizeof number, e.threshold.offset + level).ptr;
  std::string value = e.threshold.value;
  value.replace(value.find("{}"), 2, std::string(number, end));
  for (const std::string& k : e.threshold.keys) out.push_back(k + "=" + value);
  return out;
}

std::vector<std::string> condition_overrides(const Experiment& e, const Variant& condition) {
  std::vector<std::string> out;
  append(out, e.scene_set);
  append(out, condition.set);
  return out;
}

std::vector<std::string> material_overrides(const Experiment& e, const Variant& condition, const Variant& material) {
  std::vector<std::string> out;
  append(out, e.scene_set);
  append(out, condition.set);
  append(out, material.set);
  return out;
}

}  // namespace ps::study
