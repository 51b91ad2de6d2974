#pragma once
/// SHA-256 from OpenSSL's libcrypto (the distribution's), never a hash of our
/// own: the flight recorder's chain (docs/recording.md) and the mapping's
/// content hash.

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

namespace andros {

using Sha256Digest = std::array<std::uint8_t, 32>;

/// An incremental SHA-256. Throws RuntimeError when libcrypto cannot make one.
class Sha256 {
 public:
  Sha256();
  ~Sha256();
  Sha256(const Sha256&) = delete;
  Sha256& operator=(const Sha256&) = delete;

  Sha256& update(std::string_view bytes);
  Sha256& update(const Sha256Digest& digest);
  /// The digest of everything given since construction (or the last finish),
  /// and a fresh start.
  Sha256Digest finish();

 private:
  struct Ctx;
  std::unique_ptr<Ctx> ctx_;
};

Sha256Digest sha256(std::string_view bytes);
/// 64 lower-case hex digits.
std::string to_hex(const Sha256Digest& digest);
std::string sha256_hex(std::string_view bytes);

}  // namespace andros
