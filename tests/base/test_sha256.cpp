// SHA-256 (the flight recorder's chain, the mapping's content hash): the
// known answers of FIPS 180-2, whole and in pieces, and the fresh start
// after each digest.
#include <gtest/gtest.h>

#include <string>

#include "andros/base/sha256.hpp"

namespace andros {
namespace {

constexpr const char* kTwoBlocks = "abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq";

TEST(Sha256, KnownAnswers) {
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256_hex(kTwoBlocks), "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(sha256_hex(std::string(1'000'000, 'a')),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(Sha256, InPiecesAndAfreshAfterEachDigest) {
  Sha256 sha;
  const std::string text = kTwoBlocks;
  for (std::size_t i = 0; i < text.size(); i += 5) sha.update(std::string_view(text).substr(i, 5));
  const auto first = sha.finish();
  EXPECT_EQ(to_hex(first), "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(to_hex(sha.update("abc").finish()), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  // A digest hashed in (the recorder's chain): the same as its 32 bytes.
  const std::string bytes(first.begin(), first.end());
  EXPECT_EQ(sha.update(first).finish(), sha256(bytes));
}

}  // namespace
}  // namespace andros
