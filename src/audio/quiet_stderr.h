// stderr pointed at /dev/null for a scope (the OpenAL device opens of audio/live_audio.h and
// vibration/sound_out.h).
#pragma once

#include <fcntl.h>
#include <unistd.h>

#include <cstdio>

namespace ps::audio {

// libasound and OpenAL Soft print their own diagnostics to stderr when a device cannot be
// opened (a dozen "ALSA lib ..." lines on a machine without a sound card). The promise is ONE
// warning line, ours: stderr goes to /dev/null while the device opens. open() runs before the
// haptic thread starts, so nothing else of ours writes to stderr meanwhile.
class QuietStderr {
 public:
  QuietStderr() {
    std::fflush(stderr);
    saved_ = dup(STDERR_FILENO);
    const int null_fd = ::open("/dev/null", O_WRONLY);
    if (saved_ >= 0 && null_fd >= 0) dup2(null_fd, STDERR_FILENO);
    if (null_fd >= 0) ::close(null_fd);
  }
  ~QuietStderr() {
    std::fflush(stderr);
    if (saved_ >= 0) {
      dup2(saved_, STDERR_FILENO);
      ::close(saved_);
    }
  }
  QuietStderr(const QuietStderr&) = delete;
  QuietStderr& operator=(const QuietStderr&) = delete;

 private:
  int saved_ = -1;
};

}  // namespace ps::audio
