#pragma once
// Where the random tests and the fuzz targets get their choices: a seeded
// generator for the property tests, the fuzzer's bytes for the fuzz targets,
// both behind the same below(n), so that one generator of scripts serves both.

#include <cstddef>
#include <cstdint>

namespace andros::test {

/// A small generator of our own: the same numbers on every standard library.
class Random {
 public:
  explicit Random(std::uint64_t seed) : state_(seed * 0x9E3779B97F4A7C15ULL + 1) {}
  std::uint32_t below(std::uint32_t n) {
    state_ ^= state_ << 13;
    state_ ^= state_ >> 7;
    state_ ^= state_ << 17;
    return static_cast<std::uint32_t>(state_ % n);
  }
  /// A seeded generator never runs out.
  [[nodiscard]] bool exhausted() const { return false; }

 private:
  std::uint64_t state_;
};

/// The fuzzer's input as choices: each below(n) takes one byte (two when n is
/// above 256). Once the bytes run out every choice is 0 and exhausted() says
/// so, which ends a generator's loop.
class ByteChoices {
 public:
  ByteChoices(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  std::uint32_t below(std::uint32_t n) {
    std::uint32_t v = next();
    if (n > 256) v = v << 8 | next();
    return n == 0 ? 0 : v % n;
  }
  [[nodiscard]] bool exhausted() const { return at_ >= size_; }

 private:
  std::uint32_t next() { return at_ < size_ ? data_[at_++] : 0; }

  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t at_ = 0;
};

}  // namespace andros::test
