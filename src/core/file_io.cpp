#include "core/file_io.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>
#include <utility>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace ps {
namespace {

namespace fs = std::filesystem;

std::string os_reason() { return std::strerror(errno); }

// The directory holding `path`: its parent path, or "." for a bare file name.
fs::path dir_of(const fs::path& path) { return path.has_parent_path() ? path.parent_path() : fs::path("."); }

// Opens `path` read-only and fsyncs it. Linux allows fsync on a read-only descriptor, which is
// what lets us sync files that libpng or OpenImageIO wrote through their own handles.
bool sync_path(const std::string& path, int extra_flags) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | extra_flags);
  if (fd < 0) return false;
  int rc = ::fsync(fd);
  // Some file systems (e.g. a few FUSE ones) cannot fsync a directory and say EINVAL; the rename
  // is still atomic there, only its durability across a power cut is the file system's affair.
  if (rc != 0 && errno == EINVAL && (extra_flags & O_DIRECTORY)) rc = 0;
  const int saved = errno;
  ::close(fd);
  errno = saved;
  return rc == 0;
}

}  // namespace

std::optional<std::string> read_whole_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  return std::move(text).str();
}

Status prepare_output_dir(const std::string& path, bool* created) {
  if (created != nullptr) *created = false;
  if (path.empty()) return make_error("output path is empty (give a file name, e.g. out.png)");
  const fs::path p(path);
  std::error_code ec;
  if (!p.has_filename() || fs::is_directory(p, ec))
    return make_error(path + ": is a directory, not a file (give a file name, e.g. " +
                      (p / "out.png").lexically_normal().string() + ")");
  const fs::path dir = dir_of(p);
  const fs::file_status st = fs::status(dir, ec);
  if (fs::exists(st)) {
    if (!fs::is_directory(st)) return make_error(path + ": cannot write: " + dir.string() + " is not a directory");
    if (::access(dir.c_str(), W_OK) != 0)
      return make_error(path + ": cannot write to directory " + dir.string() + ": " + os_reason());
    return ok_status();
  }
  // Only the last directory is created: a typo in a parent must not grow a tree up to the root.
  const fs::path parent = dir_of(dir);
  if (!fs::is_directory(parent, ec))
    return make_error(path + ": cannot create directory " + dir.string() + ": " + parent.string() +
                      " does not exist (only the last directory of an output path is created)");
  if (::mkdir(dir.c_str(), 0777) != 0) {
    if (errno == EEXIST && fs::is_directory(dir, ec)) return ok_status();  // made by a parallel writer
    return make_error(path + ": cannot create directory " + dir.string() + ": " + os_reason());
  }
  if (created != nullptr) *created = true;
  return ok_status();
}

Status rename_durable(const std::string& file, const std::string& target) {
  // fsync before the rename: otherwise a power cut can leave the renamed file empty.
  if (!sync_path(file, 0)) return make_error(target + ": cannot write (sync failed): " + os_reason());
  if (std::rename(file.c_str(), target.c_str()) != 0)
    return make_error(target + ": cannot move the finished file into place: " + os_reason());
  const std::string dir = dir_of(fs::path(target)).string();
  if (!sync_path(dir, O_DIRECTORY))
    return make_error(target + ": written, but syncing directory " + dir + " failed: " + os_reason());
  return ok_status();
}

Result<TempFile> TempFile::create(const std::string& target) {
  const fs::path t(target);
  std::string pattern = (dir_of(t) / ("." + t.filename().string() + ".XXXXXX")).string();
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  const int fd = ::mkostemp(name.data(), O_CLOEXEC);
  if (fd < 0) return make_error(target + ": cannot create a temporary file next to it: " + os_reason());
  // mkstemp makes the file 0600; outputs are read by others (viewers, CI artefacts): 0644 is what
  // a plain open() gives under the usual umask 022. Reading the real umask is not thread-safe.
  (void)::fchmod(fd, 0644);
  return TempFile(target, std::string(name.data()), fd);
}

TempFile::TempFile(std::string target, std::string path, int fd)
    : target_(std::move(target)), path_(std::move(path)), fd_(fd), pending_(true) {}

TempFile::TempFile(TempFile&& other) noexcept
    : target_(std::move(other.target_)), path_(std::move(other.path_)),
      fd_(std::exchange(other.fd_, -1)), pending_(std::exchange(other.pending_, false)) {}

TempFile& TempFile::operator=(TempFile&& other) noexcept {
  if (this != &other) {
    discard();
    target_ = std::move(other.target_);
    path_ = std::move(other.path_);
    fd_ = std::exchange(other.fd_, -1);
    pending_ = std::exchange(other.pending_, false);
  }
  return *this;
}

TempFile::~TempFile() { discard(); }

Status TempFile::write(std::string_view bytes) {
  if (fd_ < 0) return make_error(target_ + ": cannot write: temporary file already closed");
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd_, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return make_error(target_ + ": cannot write: " + (n == 0 ? "no progress" : os_reason()));
    done += static_cast<std::size_t>(n);
  }
  return ok_status();
}

Status TempFile::close() {
  if (fd_ < 0) return ok_status();
  const int rc = ::close(std::exchange(fd_, -1));
  if (rc != 0 && errno != EINTR) return make_error(target_ + ": cannot write: " + os_reason());
  return ok_status();
}

Status TempFile::publish() {
  if (!pending_) return make_error(target_ + ": cannot publish: temporary file already gone");
  if (Status s = close(); !s) return s;
  Status renamed = rename_durable(path_, target_);
  // A failure after the rename (directory sync) leaves no temp file to remove.
  if (renamed || ::access(path_.c_str(), F_OK) != 0) pending_ = false;
  if (!renamed) return renamed;
  return ok_status();
}

void TempFile::discard() {
  if (fd_ >= 0) ::close(std::exchange(fd_, -1));
  if (pending_) ::unlink(path_.c_str());
  pending_ = false;
}

Status write_file_atomic(const std::string& path, std::string_view bytes) {
  if (Status s = prepare_output_dir(path); !s) return s;
  Result<TempFile> temp = TempFile::create(path);
  if (!temp) return temp.error();
  if (Status s = temp->write(bytes); !s) return s;
  return temp->publish();
}

}  // namespace ps
