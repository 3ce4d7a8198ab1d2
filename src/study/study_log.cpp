#include "study/study_log.h"

#include <algorithm>
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>
#include <fstream>
#include <iterator>
#include <sstream>

#include <openssl/evp.h>

#include "maze/maze_log.h"

namespace ps::study {

std::string file_sha256(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return sha256_hex(std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>()));
}

DirLock::DirLock(const std::string& dir) : fd_(::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC)) {
  if (fd_ >= 0 && ::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    ::close(fd_);
    fd_ = -1;
  }
}

DirLock::~DirLock() {
  if (fd_ >= 0) ::close(fd_);
}

namespace {
constexpr std::string_view kChecksumMember = ",\"sha256\":\"";
}  // namespace

std::string sha256_hex(std::string_view data) {
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int size = 0;
  // EVP_Digest: the one-shot form of OpenSSL 3's digest API (SHA256() is deprecated there).
  if (EVP_Digest(data.data(), data.size(), digest, &size, EVP_sha256(), nullptr) != 1) return {};
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  for (unsigned int i = 0; i < size; ++i) {
    out += kHex[digest[i] >> 4];
    out += kHex[digest[i] & 15];
  }
  return out;
}

std::string seal_line(const std::string& payload, const std::string& prev) {
  // payload is "{...}": the member goes before its closing brace.
  const std::string body = payload.substr(0, payload.size() - 1);
  return body + std::string(kChecksumMember) + sha256_hex(prev + body) + "\"}";
}

namespace {

// One line checked against `prev`; throws the reason.
LogLine check_line(const std::string& text, const std::string& prev) {
  const std::size_t at = text.rfind(kChecksumMember);
  if (at == std::string::npos || text.size() != at + kChecksumMember.size() + 64 + 2)
    throw std::runtime_error("no \"sha256\" checksum at the line's end");
  LogLine l;
  l.checksum = text.substr(at + kChecksumMember.size(), 64);
  // The checksum first: a changed line is named as changed, whether or not it is still JSON.
  if (sha256_hex(prev + text.substr(0, at)) != l.checksum)
    throw std::runtime_error("checksum does not match: the line, or one before it, was changed after it was written");
  l.json = nlohmann::json::parse(text);
  if (!l.json.is_object() || !l.json.contains("type")) throw std::runtime_error("a log line is an object with a \"type\"");
  return l;
}

}  // namespace

Result<TrialLog> read_trial_log(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return make_error(path + ": cannot open the trial log (`study run` writes DIR/PARTICIPANT/trials.jsonl)");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  TrialLog log;
  if (const auto cut = maze::torn_last_line(text)) {
    text.resize(text.size() - cut->size());
    log.torn = path + ":" + std::to_string(std::count(text.begin(), text.end(), '\n') + 1) +
               ": the last line is cut off (" + std::to_string(cut->size()) + " bytes: the run stopped while writing it): left out";
  }
  std::istringstream lines(text);
  std::string prev;
  int n = 0;
  for (std::string line; std::getline(lines, line);) {
    ++n;
    try {
      LogLine l = check_line(line, prev);
      l.number = n;
      if (n == 1 && l.json.value("type", "") != "session_start") throw std::runtime_error("the first line must be session_start");
      prev = l.checksum;
      log.lines.push_back(std::move(l));
    } catch (const std::exception& e) {
      return make_error(path + ":" + std::to_string(n) + ": " + e.what());
    }
  }
  if (log.lines.empty()) return make_error(path + ":1: empty trial log: no session_start line");
  return log;
}

}  // namespace ps::study
