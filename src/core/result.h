// Error values for runtime failures (missing file, bad scene, shader error, no context).
// No exception crosses the render or haptic loop: functions that can fail return Result<T>
// or Status, whose message is already one user-facing line ("file:line: what is wrong").
#pragma once

#include <cassert>
#include <string>
#include <utility>
#include <variant>

namespace ps {

struct Error {
  std::string message;
};

template <class T>
class [[nodiscard]] Result {
 public:
  Result(T value) : v_(std::move(value)) {}        // NOLINT(google-explicit-constructor)
  Result(Error error) : v_(std::move(error)) {}    // NOLINT(google-explicit-constructor)

  bool ok() const { return v_.index() == 0; }
  explicit operator bool() const { return ok(); }

  T& value() & {
    assert(ok() && "Result::value() called on an error; check ok() first");
    return std::get<0>(v_);
  }
  const T& value() const& {
    assert(ok() && "Result::value() called on an error; check ok() first");
    return std::get<0>(v_);
  }
  T&& value() && {
    assert(ok() && "Result::value() called on an error; check ok() first");
    return std::get<0>(std::move(v_));
  }
  T* operator->() { return &value(); }
  const T* operator->() const { return &value(); }
  T& operator*() { return value(); }

  const Error& error() const {
    assert(!ok() && "Result::error() called on a value; check ok() first");
    return std::get<1>(v_);
  }

 private:
  std::variant<T, Error> v_;
};

struct Ok {};
using Status = Result<Ok>;

inline Error make_error(std::string message) { return Error{std::move(message)}; }
inline Status ok_status() { return Ok{}; }

}  // namespace ps
