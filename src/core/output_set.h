// All the files one command writes, published together or not at all (docs/errors.md: a failed
// command leaves nothing behind). Use:
//
//   OutputSet out;
//   if (Status s = out.add(args.image); !s) return s;      // 1. check every path BEFORE the work
//   if (Status s = out.add(args.stats); !s) return s;
//   ... render ...
//   if (Status s = stage_image(out, args.image, img); !s) return s;   // 2. write each to a temp
//   if (Status s = out.stage_text(args.stats, json); !s) return s;
//   return out.publish();                                   // 3. rename all into place
//
// Returning early at any step destroys the set, which removes every temp file and any directory
// add() created: none of the outputs appears. Single-threaded (one command's main thread).
#pragma once

#include <functional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "core/file_io.h"
#include "core/result.h"

namespace ps {

class OutputSet {
 public:
  OutputSet() = default;
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;
  ~OutputSet() { discard(); }

  // Checks `path` now: the directory rule of prepare_output_dir (a missing last directory is
  // created here, and removed again if the set is never published), the directory is writable,
  // `path` is not a directory and not already in the set. Errors name the path.
  Status add(const std::string& path);

  // Writes `path`'s content to a temp file in its directory: `write` gets the temp file's name
  // and writes it by name (libpng, OpenImageIO, std::ofstream all can). Adds `path` first if it
  // was not added (a replay names its frames as it goes).
  Status stage(const std::string& path, const std::function<Status(const std::string& file)>& write);
  Status stage_text(const std::string& path, std::string_view text);

  // Renames every staged file over its target (rename_durable), in staging order. Call it only
  // when every stage() succeeded. A rename can fail only if the directory changed under us after
  // add() checked it; then the outputs renamed before it stay and the error names the one that
  // failed.
  Status publish();

  // Removes every unpublished temp file and the directories add() created (if empty).
  void discard();

  std::size_t staged_count() const { return staged_.size(); }

 private:
  Result<TempFile> open_temp(const std::string& path);  // add() if new, then a TempFile
  std::set<std::string> paths_;            // added (lexically normal); a replay adds thousands
  std::vector<std::string> created_dirs_;  // made by add(), removed by discard()
  std::vector<TempFile> staged_;
};

}  // namespace ps
