#pragma once
/// @file
/// A fixed-capacity FIFO (no allocation). Pushing into a full buffer drops the oldest element and
/// reports it, so a caller can count overflows.

#include <array>
#include <cstddef>

namespace hil::estimator {

template <typename T, std::size_t N>
class RingBuffer {
 public:
  /// Appends; returns false when the oldest element had to be dropped to make room.
  bool Push(const T& v) {
    bool dropped = false;
    if (size_ == N) {
      PopFront();
      dropped = true;
    }
    data_[(head_ + size_) % N] = v;
    ++size_;
    return !dropped;
  }
  void PopFront() {
    if (size_ == 0) return;
    head_ = (head_ + 1) % N;
    --size_;
  }
  const T& front() const { return data_[head_]; }
  const T& back() const { return data_[(head_ + size_ - 1) % N]; }
  const T& operator[](std::size_t i) const { return data_[(head_ + i) % N]; }
  T& operator[](std::size_t i) { return data_[(head_ + i) % N]; }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  void clear() { head_ = size_ = 0; }
  static constexpr std::size_t capacity() { return N; }

 private:
  std::array<T, N> data_{};
  std::size_t head_ = 0, size_ = 0;
};

}  // namespace hil::estimator
