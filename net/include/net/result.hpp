// net/result.hpp — Result<T, E>: a value or an error, for input that must not throw (network
// bytes, URLs). `if (r) use(r.value()); else report(r.error());`. value() on an error and error()
// on a value are programming errors (checked with assert).
#pragma once

#include <cassert>
#include <utility>
#include <variant>

namespace net {

template <class T, class E>
class Result {
 public:
  static Result success(T v) { return Result(std::in_place_index<0>, std::move(v)); }
  static Result failure(E e) { return Result(std::in_place_index<1>, std::move(e)); }
  Result(T v) : v_(std::in_place_index<0>, std::move(v)) {}  // NOLINT: implicit success

  bool ok() const noexcept { return v_.index() == 0; }
  explicit operator bool() const noexcept { return ok(); }
  const T& value() const& {
    assert(ok());
    return std::get<0>(v_);
  }
  T& value() & {
    assert(ok());
    return std::get<0>(v_);
  }
  T&& value() && {
    assert(ok());
    return std::get<0>(std::move(v_));
  }
  const E& error() const& {
    assert(!ok());
    return std::get<1>(v_);
  }

 private:
  template <std::size_t I, class A>
  Result(std::in_place_index_t<I> i, A&& a) : v_(i, std::forward<A>(a)) {}
  std::variant<T, E> v_;
};

}  // namespace net
