// StatusOr<T>: a T, or the non-OK Status that says why there is none.
//
// The return type of an operation that makes a value and can fail, in place
// of a Status return plus an out-parameter. Made from a T (OK) or from a
// non-OK Status; value() and the dereference operators may only be used when
// ok().
//
// Invariant: ok() exactly when a value is held. A StatusOr made from an OK
// Status would break it, so it holds Internal("OK status given to StatusOr")
// instead.
//
// Thread-safety: like T; distinct objects are independent.

#ifndef LOCATOR_STATUS_OR_H_
#define LOCATOR_STATUS_OR_H_

#include <cassert>
#include <optional>
#include <type_traits>
#include <utility>

#include "locator/status.h"

namespace locator {

template <typename T>
class [[nodiscard]] StatusOr {
 public:
  static_assert(!std::is_same_v<std::remove_cv_t<T>, Status>,
                "StatusOr<Status> is meaningless; return a Status");

  // A failure: `status` must not be OK.
  StatusOr(Status status)  // NOLINT(google-explicit-constructor)
      : status_(status.ok() ? Status::Internal("OK status given to StatusOr")
                            : std::move(status)) {}
  // A value.
  StatusOr(T value)  // NOLINT(google-explicit-constructor)
      : value_(std::move(value)) {}
  // A value converted from U (e.g. unique_ptr<Derived> into
  // unique_ptr<Base>).
  template <typename U>
  requires(std::is_constructible_v<T, U&&> &&
           !std::is_same_v<std::decay_t<U>, T> &&
           !std::is_same_v<std::decay_t<U>, Status> &&
           !std::is_same_v<std::decay_t<U>, StatusOr<T>>)
      StatusOr(U&& value)  // NOLINT(google-explicit-constructor)
      : value_(T(std::forward<U>(value))) {}

  // Whether a value is held.
  bool ok() const { return value_.has_value(); }
  // OK when a value is held, else why not.
  const Status& status() const& { return status_; }
  Status status() && { return std::move(status_); }

  // The value; ok() must hold.
  const T& value() const& {
    assert(ok());
    return *value_;
  }
  T& value() & {
    assert(ok());
    return *value_;
  }
  T&& value() && {
    assert(ok());
    return *std::move(value_);
  }
  const T& operator*() const& { return value(); }
  T& operator*() & { return value(); }
  T&& operator*() && { return std::move(*this).value(); }
  const T* operator->() const { return &value(); }
  T* operator->() { return &value(); }

 private:
  Status status_;  // OK exactly when value_ holds one
  std::optional<T> value_;
};

}  // namespace locator

#endif  // LOCATOR_STATUS_OR_H_
