#include "core/output_set.h"

#include <filesystem>

#include <unistd.h>

namespace ps {
namespace {

std::string normal(const std::string& path) {
  return std::filesystem::path(path).lexically_normal().string();
}

}  // namespace

Status OutputSet::add(const std::string& path) {
  const std::string key = normal(path);
  if (paths_.count(key) != 0)
    return make_error(path + ": named as two outputs of one command (give each output its own file)");
  bool created = false;
  if (Status s = prepare_output_dir(path, &created); !s) return s;
  if (created) created_dirs_.push_back(std::filesystem::path(key).parent_path().string());
  paths_.insert(key);
  return ok_status();
}

Result<TempFile> OutputSet::open_temp(const std::string& path) {
  if (paths_.count(normal(path)) == 0)
    if (Status s = add(path); !s) return s.error();
  return TempFile::create(path);
}

Status OutputSet::stage(const std::string& path, const std::function<Status(const std::string& file)>& write) {
  Result<TempFile> temp = open_temp(path);
  if (!temp) return temp.error();
  // Closed before `write` opens it by name, so a replay of thousands of frames holds no
  // descriptors; the TempFile still owns (and on failure removes) the file.
  if (Status s = temp->close(); !s) return s;
  if (Status s = write(temp->path()); !s) return s;
  staged_.push_back(std::move(temp.value()));
  return ok_status();
}

Status OutputSet::stage_text(const std::string& path, std::string_view text) {
  Result<TempFile> temp = open_temp(path);
  if (!temp) return temp.error();
  if (Status s = temp->write(text); !s) return s;
  if (Status s = temp->close(); !s) return s;
  staged_.push_back(std::move(temp.value()));
  return ok_status();
}

Status OutputSet::publish() {
  for (TempFile& temp : staged_)
    if (Status s = temp.publish(); !s) {
      discard();
      return s;
    }
  staged_.clear();
  created_dirs_.clear();  // they hold published files now
  paths_.clear();
  return ok_status();
}

void OutputSet::discard() {
  staged_.clear();  // each TempFile removes its file
  // rmdir removes only empty directories: one that received a published file stays.
  for (auto it = created_dirs_.rbegin(); it != created_dirs_.rend(); ++it) ::rmdir(it->c_str());
  created_dirs_.clear();
  paths_.clear();
}

}  // namespace ps
