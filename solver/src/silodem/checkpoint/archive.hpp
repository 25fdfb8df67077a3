#pragma once
// One routine per stateful class for both directions of a checkpoint: `serialize(Archive&)` lists
// the members once, and the archive either appends them to a byte string or reads them back. The
// state is copied bit for bit (doubles as their bytes, never through text), which is what makes a
// restarted run bitwise identical to an uninterrupted one. Reading never trusts the bytes: every
// length is checked against what is left, so a damaged payload is an error, not a crash.
#include <cstdint>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "silodem/core/types.hpp"

namespace silodem {

/// Fixed-size Eigen matrices of doubles (Vec3, the contact history's per-slot springs): stored as
/// their packed bytes.
template <class T>
inline constexpr bool kPackedDoubles = false;
template <int R, int C, int O, int MR, int MC>
inline constexpr bool kPackedDoubles<Eigen::Matrix<double, R, C, O, MR, MC>> =
    R > 0 && C > 0 && sizeof(Eigen::Matrix<double, R, C, O, MR, MC>) == std::size_t(R) * std::size_t(C) * sizeof(double);

/// A checkpoint that cannot be used (damaged, truncated, another format or another case).
class CheckpointError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Archive {
 public:
  static Archive writer() { return Archive(false, {}); }
  static Archive reader(std::string bytes) { return Archive(true, std::move(bytes)); }
  bool loading() const { return loading_; }
  const std::string& bytes() const { return buf_; }
  /// After reading everything: bytes left over mean the layout differs from this build's.
  void expect_end() const {
    if (pos_ != buf_.size())
      throw CheckpointError("checkpoint payload has " + std::to_string(buf_.size() - pos_) + " bytes more than this build reads");
  }

  template <class T>
  Archive& operator&(T& v) {
    io(v);
    return *this;
  }

  /// Raw bytes of trivially copyable values (numbers, plain structs of numbers).
  void raw(void* data, std::size_t n) {
    if (n == 0) return;  // an empty vector's data() may be null, which memcpy must not see
    if (loading_) {
      if (n > buf_.size() - pos_) throw CheckpointError("checkpoint payload is truncated");
      std::memcpy(data, buf_.data() + pos_, n);
      pos_ += n;
    } else {
      buf_.append(static_cast<const char*>(data), n);
    }
  }
  /// A count of `elem` -byte items that must still fit in the payload (no allocation from garbage).
  std::uint64_t count(std::uint64_t n, std::size_t elem) {
    io_plain(n);
    if (loading_ && elem > 0 && n > (buf_.size() - pos_) / elem)
      throw CheckpointError("checkpoint payload is truncated (a list claims " + std::to_string(n) + " items)");
    return n;
  }

 private:
  Archive(bool loading, std::string bytes) : loading_(loading), buf_(std::move(bytes)) {}

  template <class T>
  void io_plain(T& v) {
    raw(&v, sizeof(T));
  }
  template <class T>
  void io(T& v) {
    static_assert(!std::is_enum_v<T>, "store an enum through its underlying integer, checked on reading");
    if constexpr (std::is_same_v<T, bool>) {
      std::uint8_t b = v ? 1 : 0;  // a bool read from any other byte than 0 or 1 would be undefined
      io_plain(b);
      if (b > 1) throw CheckpointError("checkpoint payload is damaged (a flag is neither 0 nor 1)");
      v = b == 1;
    } else if constexpr (std::is_arithmetic_v<T>) {
      io_plain(v);
    } else if constexpr (kPackedDoubles<T>) {
      raw(v.data(), sizeof(T));
    } else {
      v.serialize(*this);
    }
  }
  void io(std::string& s) {
    const std::uint64_t n = count(s.size(), 1);
    if (loading_) s.resize(n);
    raw(s.data(), n);
  }
  void io(std::vector<bool>& v) {
    const std::uint64_t n = count(v.size(), 1);
    if (loading_) v.assign(n, false);
    for (std::size_t i = 0; i < n; ++i) {
      bool b = v[i];
      io(b);
      v[i] = b;
    }
  }
  template <class T>
  void io(std::vector<T>& v) {
    constexpr bool bulk = (std::is_arithmetic_v<T> && !std::is_same_v<T, bool>) || kPackedDoubles<T>;
    const std::uint64_t n = count(v.size(), bulk ? sizeof(T) : 1);
    if (loading_) v.resize(n);
    if constexpr (bulk) {
      raw(v.data(), n * sizeof(T));
    } else {
      for (auto& e : v) io(e);
    }
  }
  template <class A, class B>
  void io(std::pair<A, B>& v) {
    io(v.first);
    io(v.second);
  }
  template <class T>
  void io(std::optional<T>& v) {
    bool has = v.has_value();
    io(has);
    if (loading_) v = has ? std::optional<T>(T{}) : std::nullopt;
    if (has) io(*v);
  }

  bool loading_;
  std::string buf_;
  std::size_t pos_ = 0;
};

}  // namespace silodem
