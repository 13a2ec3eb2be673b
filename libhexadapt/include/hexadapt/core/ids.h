// Typed ids and the vectors indexed by them.
//
// A CellId cannot index a node array: IdVector<NodeId, T> only accepts NodeId, so mixing up
// index spaces is a compile error rather than a silent bug. Ids are 32-bit (a 512^3 grid has
// 134 M cells, well inside the range); the invalid id is -1.
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

namespace hexadapt {

using index_t = std::int32_t;

template <class Tag>
class Id {
 public:
  constexpr Id() = default;
  constexpr explicit Id(index_t v) : v_(v) {}
  template <class Int, class = std::enable_if_t<std::is_integral_v<Int> &&
                                                !std::is_same_v<Int, index_t>>>
  constexpr explicit Id(Int v) : v_(static_cast<index_t>(v)) {}

  static constexpr Id invalid() { return Id(); }
  constexpr bool valid() const { return v_ >= 0; }
  constexpr index_t value() const { return v_; }
  /// The id as a std::size_t, for indexing plain containers.
  constexpr std::size_t idx() const { return static_cast<std::size_t>(v_); }

  constexpr Id& operator++() { ++v_; return *this; }
  friend constexpr bool operator==(Id a, Id b) { return a.v_ == b.v_; }
  friend constexpr bool operator!=(Id a, Id b) { return a.v_ != b.v_; }
  friend constexpr bool operator<(Id a, Id b) { return a.v_ < b.v_; }
  friend constexpr bool operator>(Id a, Id b) { return a.v_ > b.v_; }
  friend constexpr bool operator<=(Id a, Id b) { return a.v_ <= b.v_; }
  friend constexpr bool operator>=(Id a, Id b) { return a.v_ >= b.v_; }

 private:
  index_t v_ = -1;
};

struct CellTag {};
struct NodeTag {};
struct HalfFaceTag {};
struct MaterialTag {};

using CellId = Id<CellTag>;
using NodeId = Id<NodeTag>;
using HalfFaceId = Id<HalfFaceTag>;

/// A std::vector that is indexed by one id type only.
template <class IdT, class T>
class IdVector {
 public:
  using value_type = T;
  IdVector() = default;
  explicit IdVector(std::size_t n, const T& v = T()) : data_(n, v) {}
  explicit IdVector(std::vector<T> data) : data_(std::move(data)) {}

  typename std::vector<T>::reference operator[](IdT id) { return data_[id.idx()]; }
  typename std::vector<T>::const_reference operator[](IdT id) const { return data_[id.idx()]; }

  std::size_t size() const { return data_.size(); }
  bool empty() const { return data_.empty(); }
  void resize(std::size_t n, const T& v = T()) { data_.resize(n, v); }
  void assign(std::size_t n, const T& v) { data_.assign(n, v); }
  void reserve(std::size_t n) { data_.reserve(n); }
  void push_back(const T& v) { data_.push_back(v); }
  auto begin() { return data_.begin(); }
  auto end() { return data_.end(); }
  auto begin() const { return data_.begin(); }
  auto end() const { return data_.end(); }
  std::vector<T>& raw() { return data_; }
  const std::vector<T>& raw() const { return data_; }

 private:
  std::vector<T> data_;
};

/// Iterates ids first..last-1: `for (CellId c : id_range<CellId>(mesh.n_cells()))`.
template <class IdT>
class IdRange {
 public:
  class iterator {
   public:
    explicit iterator(index_t v) : v_(v) {}
    IdT operator*() const { return IdT(v_); }
    iterator& operator++() { ++v_; return *this; }
    bool operator!=(const iterator& o) const { return v_ != o.v_; }
    bool operator==(const iterator& o) const { return v_ == o.v_; }

   private:
    index_t v_;
  };
  IdRange(index_t first, index_t last) : first_(first), last_(last) {}
  iterator begin() const { return iterator(first_); }
  iterator end() const { return iterator(last_); }

 private:
  index_t first_, last_;
};

template <class IdT>
IdRange<IdT> id_range(index_t n) { return IdRange<IdT>(0, n); }

/// Checked narrowing of a count to index_t; throws hexadapt::Error when it does not fit.
index_t checked_index(std::size_t n, const char* what);

}  // namespace hexadapt

template <class Tag>
struct std::hash<hexadapt::Id<Tag>> {
  std::size_t operator()(hexadapt::Id<Tag> id) const noexcept {
    return std::hash<hexadapt::index_t>()(id.value());
  }
};
