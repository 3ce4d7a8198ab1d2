// Reading a file whole (read_whole_file), and output files that are never half-written
// (docs/errors.md: "nothing is written when a command fails"). Three pieces, each built on the
// one below:
//
//   prepare_output_dir  the directory rule every output path follows: the file's directory must
//                       exist, or only its LAST component may be missing (it is created, its
//                       parent must exist). `--out a/b/c/x.png` with `a/b` missing is an error
//                       naming `a/b`, never a silent mkdir -p up to the root.
//   TempFile            one file written under a unique hidden name in the target's directory
//                       (mkstemp), fsynced, renamed over the target, directory fsynced: a reader,
//                       a crash or a SIGKILL sees the old file or the complete new one.
//   write_file_atomic   TempFile for a string.
//
// OutputSet (core/output_set.h) groups several TempFiles so a command publishes all or none.
// Errors are one line naming the path and the OS reason.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "core/result.h"

namespace ps {

// The whole file's bytes, or nullopt when it cannot be opened (errno says why, as open(2) left it):
// each reader words its own error, naming what the file should have been.
std::optional<std::string> read_whole_file(const std::string& path);

// Applies the directory rule to the directory that will hold `path` (its parent path; "." when
// it has none). Sets `*created` when this call made the directory (so a caller that fails later
// can remove it again). Errors: "<dir>: cannot create output directory: parent <p> does not
// exist", "<dir>: output directory is a file", "<path>: is a directory, not a file".
Status prepare_output_dir(const std::string& path, bool* created = nullptr);

// fsync(2) of `file` (opened by name, so it works for files another library wrote), rename(2)
// onto `target`, then fsync of target's directory so the rename itself survives a power cut.
// `file` and `target` must be in the same directory (rename is atomic only there).
Status rename_durable(const std::string& file, const std::string& target);

// A uniquely named temp file next to `target`: "<dir>/.<name>.XXXXXX" (hidden, and never the
// target's own name, so a killed writer leaves the target untouched). The destructor removes the
// temp file unless publish() succeeded. Move-only.
class TempFile {
 public:
  // Does NOT apply the directory rule (call prepare_output_dir first).
  static Result<TempFile> create(const std::string& target);

  TempFile(TempFile&& other) noexcept;
  TempFile& operator=(TempFile&& other) noexcept;
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  ~TempFile();

  const std::string& path() const { return path_; }      // the temp file
  const std::string& target() const { return target_; }  // where publish() puts it

  // Appends `bytes` through the open descriptor. For writers that open files by name (libpng,
  // OpenImageIO), write to path() instead; publish() syncs whatever is there.
  Status write(std::string_view bytes);
  // Closes the descriptor (keeping the temp file), e.g. before handing path() to another writer
  // or to hold many staged files without running out of descriptors.
  Status close();
  // Closes the descriptor, then rename_durable(path(), target()). Errors name target().
  Status publish();
  // Removes the temp file now (also done by the destructor).
  void discard();

 private:
  TempFile(std::string target, std::string path, int fd);
  std::string target_, path_;
  int fd_ = -1;
  bool pending_ = false;  // the temp file exists and is not yet published or removed
};

// prepare_output_dir + TempFile + publish: `path` holds either its old content or `bytes`.
Status write_file_atomic(const std::string& path, std::string_view bytes);

}  // namespace ps
