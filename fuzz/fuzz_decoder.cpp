// libFuzzer target: the frame decoder. Whatever bytes arrive, in whatever
// chunks, the decoder finds the same frames, every frame it calls valid is a
// real frame at its offset, and its counts add up.
#include <cstdint>
#include <cstdlib>
#include <span>
#include <vector>

#include "andros/protocol/decoder.hpp"
#include "fuzz_check.hpp"

namespace {

struct Seen {
  std::uint64_t offset;
  andros::protocol::DataBytes data;
  bool valid;
  bool operator==(const Seen&) const = default;
};

std::vector<Seen> decode(std::span<const std::uint8_t> bytes, std::size_t chunk,
                         andros::protocol::DecoderStats* stats) {
  andros::protocol::Decoder decoder;
  std::vector<Seen> seen;
  const auto sink = [&](const andros::protocol::DecodedFrame& f) { seen.push_back({f.offset, f.data, f.valid}); };
  for (std::size_t pos = 0; pos < bytes.size(); pos += chunk) {
    decoder.push(bytes.subspan(pos, std::min(chunk, bytes.size() - pos)), sink);
  }
  decoder.finish();
  *stats = decoder.stats();
  return seen;
}

}  // namespace

using andros::fuzz::check;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::size_t chunk = 1 + data[0] % 40;  // the first byte picks a chunking
  const std::span bytes(data + 1, size - 1);

  andros::protocol::DecoderStats whole_stats, chunked_stats;
  const auto whole = decode(bytes, bytes.size() + 1, &whole_stats);
  const auto chunked = decode(bytes, chunk, &chunked_stats);
  check(whole == chunked);
  check(whole_stats.frames == whole_stats.valid + whole_stats.bad_checksum + whole_stats.invalid);
  check(whole_stats.bytes_total == bytes.size());
  check(whole_stats.bytes_skipped <= bytes.size());
  for (const auto& f : whole) {
    if (!f.valid) continue;
    const auto frame = andros::protocol::encode(f.data);
    check(f.offset + frame.size() <= bytes.size());
    check(std::equal(frame.begin(), frame.end(), bytes.begin() + static_cast<std::ptrdiff_t>(f.offset)));
    check(andros::protocol::validation_errors(f.data).empty());
  }
  return 0;
}
