// A minimal read-only view of contiguous elements (C++17 has no std::span).
#pragma once

#include <cstddef>

namespace hexadapt {

template <class T>
class Span {
 public:
  constexpr Span() = default;
  constexpr Span(const T* first, std::size_t n) : first_(first), n_(n) {}
  constexpr const T* begin() const { return first_; }
  constexpr const T* end() const { return first_ + n_; }
  constexpr std::size_t size() const { return n_; }
  constexpr bool empty() const { return n_ == 0; }
  constexpr const T& operator[](std::size_t i) const { return first_[i]; }

 private:
  const T* first_ = nullptr;
  std::size_t n_ = 0;
};

}  // namespace hexadapt
