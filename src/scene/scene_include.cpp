// `include = ["materials/lib.toml", ...]`: material libraries (docs/scene-format.md, Includes).
// An included file holds only [materials.NAME] tables and its own `include`; paths are relative
// to the file that names them. Within one file, its own definitions replace those of its
// includes; two includes that define one name differently are an error unless the including
// file defines that name itself. A file reached twice by different routes (a diamond) is not a
// cycle; a file that includes itself, directly or not, is. A renamed library keeps its old
// file for one release holding only `renamed_to = "NEW.toml"`: it stands for NEW.toml and says
// so on stderr each time it is loaded.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "scene/scene_convert.h"
#include "scene/scene_io.h"
#include "scene/toml_text.h"

namespace ps::scene_detail {
namespace {

namespace fs = std::filesystem;

constexpr int kMaxIncludedFiles = 64;  // a hostile diamond chain cannot read files forever
constexpr int kMaxIncludeDepth = 16;

// One file being resolved: how messages name it, where its relative paths point, and its
// canonical path (empty for text that is not a file, e.g. the embedded default scene).
struct FileInfo {
  std::string name;
  std::string path;  // resolved
  std::string base_dir;
  std::string canonical;
};

struct Walk {
  ParseContext& ctx;
  std::vector<FileInfo> stack;  // the include chain, for cycle messages
  int files_read = 0;
  int next_order = 0;
};

using MaterialSet = std::map<std::string, IncludedMaterial, std::less<>>;

std::string at(const FileInfo& file, const toml::node& node) {
  const auto line = std::max<long>(1, static_cast<long>(node.source().begin.line));
  return file.name + ":" + std::to_string(line);
}

// The include entries of a document: a string or an array of strings, with their nodes; for a
// renamed library (`library`: an included file; checked by load), its new name.
Result<std::vector<const toml::node*>> include_entries(const FileInfo& file,
                                                       const toml::table& doc, bool library) {
  std::vector<const toml::node*> out;
  const toml::node* renamed = library ? doc.get("renamed_to") : nullptr;
  if (renamed) return std::vector<const toml::node*>{renamed};
  const toml::node* node = doc.get("include");
  if (!node) return out;
  if (node->is_string()) return std::vector<const toml::node*>{node};
  const toml::array* array = node->as_array();
  const std::string shape = ": 'include' must be a file name or an array of file names "
                            "(e.g. include = [\"materials/virtual_universe.toml\"])";
  if (!array) return make_error(at(file, *node) + shape);
  for (const toml::node& entry : *array) {
    if (!entry.is_string()) return make_error(at(file, entry) + shape);
    out.push_back(&entry);
  }
  return out;
}

Result<std::string> read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return make_error("cannot open");
  // Read at most one byte past the limit: special files report no size.
  std::string text(kMaxSceneFileBytes + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  if (text.size() > kMaxSceneFileBytes) {
    return make_error("more than the limit of " + std::to_string(kMaxSceneFileBytes) + " bytes");
  }
  return text;
}

Result<FileInfo> locate(const Walk& walk, const FileInfo& from, const toml::node& entry) {
  const std::string name = entry.value<std::string>().value_or("");
  fs::path resolved(name);
  fs::path shown(name);
  if (resolved.is_relative()) {
    resolved = fs::path(from.base_dir) / resolved;
    // Names like "<built-in default scene>" are not paths: show the resolved path instead.
    shown = from.name.starts_with('<') ? resolved : fs::path(from.name).parent_path() / shown;
  }
  resolved = resolved.lexically_normal();
  // Confined before its existence is checked (scene/path_policy.h).
  if (Status s = walk.ctx.paths.admit(resolved, "'include' names"); !s && !name.empty())
    return make_error(at(from, entry) + ": " + s.error().message);
  std::error_code ec;
  if (name.empty() || !fs::is_regular_file(resolved, ec)) {
    return make_error(at(from, entry) + ": 'include' file not found: " + resolved.string());
  }
  FileInfo file{shown.lexically_normal().string(), resolved.string(),
                resolved.parent_path().string(), fs::weakly_canonical(resolved, ec).string()};
  for (std::size_t i = 0; i < walk.stack.size(); ++i) {
    if (walk.stack[i].canonical != file.canonical) continue;
    std::string chain;
    for (std::size_t j = i; j < walk.stack.size(); ++j) chain += walk.stack[j].name + " -> ";
    return make_error(at(from, entry) + ": include cycle: " + chain + file.name);
  }
  if (walk.stack.size() >= static_cast<std::size_t>(kMaxIncludeDepth)) {
    return make_error(at(from, entry) + ": includes nested more than " +
                      std::to_string(kMaxIncludeDepth) + " deep");
  }
  if (walk.files_read >= kMaxIncludedFiles) {
    return make_error(at(from, entry) + ": more than " + std::to_string(kMaxIncludedFiles) +
                      " included files");
  }
  return file;
}

// A renamed library's old file: `renamed_to` must be its only key, a file name beside it. One
// line on stderr names both files as messages name them (relative to the including scene).
Status announce_rename(const FileInfo& file, const toml::table& doc, const toml::node& renamed) {
  const std::string to = renamed.value<std::string>().value_or("");
  if (to.empty() || doc.size() != 1 || fs::path(to).has_parent_path()) {
    return make_error(at(file, renamed) + ": 'renamed_to' must be the only key of a renamed "
                      "library, the new file's name in the same folder (e.g. renamed_to = "
                      "\"virtual_universe.toml\")");
  }
  const std::string shown = (fs::path(file.name).parent_path() / to).string();
  std::fprintf(stderr, "%s was renamed to %s; the old name goes in the next release\n",
               file.name.c_str(), shown.c_str());
  return ok_status();
}

Result<toml::table*> load(Walk& walk, const FileInfo& from, const toml::node& entry,
                          const FileInfo& file) {
  ++walk.files_read;
  Result<std::string> text = read_text(file.path);
  if (!text) {
    return make_error(at(from, entry) + ": cannot read included file " + file.name + ": " +
                      text.error().message);
  }
  Result<toml::table> parsed = parse_toml(*text, file.name);
  if (!parsed) return parsed.error();
  auto doc = std::make_unique<toml::table>(std::move(parsed.value()));
  if (const toml::node* renamed = doc->get("renamed_to")) {
    if (Status s = announce_rename(file, *doc, *renamed); !s) return s.error();
  }
  for (const auto& [key, node] : *doc) {
    if (key.str() == "include" || key.str() == "materials" || key.str() == "renamed_to") continue;
    return make_error(at(file, node) + ": an included file may hold only 'include' and "
                      "[materials.NAME] tables (found '" + std::string(key.str()) + "')");
  }
  if (const toml::node* m = doc->get("materials"); m && !m->is_table()) {
    return make_error(at(file, *m) + ": 'materials' must be a table ([materials.NAME])");
  }
  walk.ctx.included_docs.push_back(std::move(doc));
  return walk.ctx.included_docs.back().get();
}

Status collect(Walk& walk, const FileInfo& file, toml::table& doc, MaterialSet& out);

// Materials of one include entry merged into `from_includes`; a name defined differently by
// two includes is remembered in `conflicts` (an error unless the including file defines it).
Status merge_include(Walk& walk, const FileInfo& from, const toml::node& entry,
                     MaterialSet& from_includes, std::map<std::string, std::string>& conflicts) {
  Result<FileInfo> file = locate(walk, from, entry);
  if (!file) return file.error();
  Result<toml::table*> doc = load(walk, from, entry, *file);
  if (!doc) return doc.error();
  walk.stack.push_back(*file);
  MaterialSet set;
  Status s = collect(walk, *file, **doc, set);
  walk.stack.pop_back();
  if (!s) return s;
  for (auto& [name, material] : set) {
    auto [it, added] = from_includes.emplace(name, material);
    if (!added && it->second.identity != material.identity && !conflicts.count(name)) {
      conflicts[name] = at(from, entry) + ": material '" + name + "' is defined differently in " +
                        it->second.source_name + " and " + material.source_name +
                        "; define [materials." + name + "] in " + from.name + " to choose";
    }
  }
  return ok_status();
}

// All materials `doc` provides: those of its includes, replaced by its own definitions.
Status collect(Walk& walk, const FileInfo& file, toml::table& doc, MaterialSet& out) {
  Result<std::vector<const toml::node*>> entries =
      include_entries(file, doc, /*library=*/walk.stack.size() > 1);
  if (!entries) return entries.error();
  std::map<std::string, std::string> conflicts;
  for (const toml::node* entry : *entries) {
    if (Status s = merge_include(walk, file, *entry, out, conflicts); !s) return s;
  }
  toml::table* own = doc["materials"].as_table();
  for (const auto& [name, message] : conflicts) {
    if (!own || !own->contains(name)) return make_error(message);
  }
  if (!own) return ok_status();
  std::vector<std::pair<std::string, toml::table*>> tables;
  for (auto& [key, node] : *own) {
    toml::table* table = node.as_table();
    if (!table) return make_error(at(file, node) + ": 'materials." + std::string(key.str()) +
                                  "' must be a table ([materials." + std::string(key.str()) + "])");
    tables.emplace_back(std::string(key.str()), table);
  }
  // File order (toml++ iterates keys sorted), so materials are numbered as written.
  std::stable_sort(tables.begin(), tables.end(), [](const auto& a, const auto& b) {
    return a.second->source().begin.line < b.second->source().begin.line;
  });
  for (auto& [name, table] : tables) {
    const std::string line = std::to_string(table->source().begin.line);
    out[name] = IncludedMaterial{table, file.name, file.base_dir, file.canonical + ":" + line,
                                 walk.next_order++};
  }
  return ok_status();
}

}  // namespace

Status resolve_includes(toml::table& root, ParseContext& ctx) {
  if (!root.contains("include")) return ok_status();
  std::error_code ec;
  const fs::path self = fs::path(ctx.base_dir) / fs::path(ctx.source_name).filename();
  const bool is_file = fs::is_regular_file(self, ec);
  const FileInfo file{ctx.source_name, self.string(), ctx.base_dir,
                      is_file ? fs::weakly_canonical(self, ec).string() : ""};
  Walk walk{ctx, {file}};
  MaterialSet all;
  if (Status s = collect(walk, file, root, all); !s) return s;
  // The scene's own materials stay in `root` (converted with the scene's context).
  const toml::table* own = root["materials"].as_table();
  for (auto& [name, material] : all) {
    if (!own || !own->contains(name)) ctx.included.emplace(name, std::move(material));
  }
  return ok_status();
}

}  // namespace ps::scene_detail
