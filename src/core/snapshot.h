// A single-writer snapshot (seqlock) for handing a small trivially copyable struct from one
// thread to others without locks: the haptic thread publishes its state at 1 kHz, the render
// thread publishes the local surface model once per frame. Every byte is stored in an
// std::atomic word, so there is no data race in the C++ memory model (TSan-clean); the
// sequence number makes readers retry instead of seeing a torn copy.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <cstring>
#include <type_traits>

namespace ps {

template <class T>
class Snapshot {
  static_assert(std::is_trivially_copyable_v<T>, "Snapshot<T>: T must be trivially copyable");
  static constexpr std::size_t kWords = (sizeof(T) + 7) / 8;

 public:
  Snapshot() { publish(T{}); }
  Snapshot(const Snapshot&) = delete;
  Snapshot& operator=(const Snapshot&) = delete;

  // Only ONE thread may call publish() (single writer); never blocks.
  void publish(const T& value) {
    std::array<std::uint64_t, kWords> w{};
    std::memcpy(w.data(), &value, sizeof(T));
    const std::uint64_t s = seq_.load(std::memory_order_relaxed);
    seq_.store(s + 1, std::memory_order_relaxed);  // odd: write in progress
    // release on each word orders the odd sequence before it (a reader that sees a new word
    // then sees the odd/next sequence on its re-check and retries).
    for (std::size_t i = 0; i < kWords; ++i) words_[i].store(w[i], std::memory_order_release);
    seq_.store(s + 2, std::memory_order_release);
  }

  // Any thread; retries while a write is in progress (the writer holds it for ~100 ns).
  T read() const {
    std::array<std::uint64_t, kWords> w{};
    for (;;) {
      const std::uint64_t s0 = seq_.load(std::memory_order_acquire);
      if (s0 & 1u) continue;
      for (std::size_t i = 0; i < kWords; ++i) w[i] = words_[i].load(std::memory_order_acquire);
      if (seq_.load(std::memory_order_relaxed) == s0) break;
    }
    T out;
    std::memcpy(static_cast<void*>(&out), w.data(), sizeof(T));  // T is trivially copyable
    return out;
  }

  // Number of completed publishes (including the initial default value).
  std::uint64_t version() const { return seq_.load(std::memory_order_acquire) / 2; }

 private:
  std::atomic<std::uint64_t> seq_{0};
  std::array<std::atomic<std::uint64_t>, kWords> words_{};
};

}  // namespace ps
