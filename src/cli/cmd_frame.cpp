// `andros-bridge frame encode|decode`: the protocol's reference codec.
#include <sys/stat.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "andros/base/error.hpp"
#include "andros/base/text.hpp"
#include "andros/protocol/decoder.hpp"
#include "andros/protocol/frame.hpp"
#include "andros/protocol/json.hpp"
#include "commands.hpp"

namespace andros::cli {
namespace {

struct EncodeOptions {
  std::vector<std::string> hex;
  bool raw = false;
};

struct DecodeOptions {
  std::string input = "-";
  std::string code;
};

void run_encode(const EncodeOptions& opt) {
  std::string digits;
  for (const auto& part : opt.hex) {
    for (const char c : part) {
      if (c != ' ' && c != '\t') digits += c;
    }
  }
  protocol::DataBytes data;
  try {
    data = protocol::parse_data_hex(digits);
  } catch (const InputError& e) {
    throw InputError("frame encode: " + e.message());
  }
  const auto frame = protocol::encode(data);
  if (opt.raw) {
    std::fwrite(frame.data(), 1, frame.size(), stdout);
  } else {
    std::printf("%s\n", protocol::to_hex(frame).c_str());
  }
}

int run_decode(const DecodeOptions& opt) {
  std::optional<std::uint8_t> code;
  if (!opt.code.empty()) code = parse_code(opt.code, SourcePos{"--code"});

  const bool from_stdin = opt.input == "-";
  std::FILE* in = from_stdin ? stdin : std::fopen(opt.input.c_str(), "rb");
  if (in == nullptr) {
    throw InputError(SourcePos{opt.input}, std::string("cannot open: ") + std::strerror(errno));
  }
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> closer(from_stdin ? nullptr : in,
                                                               [](std::FILE* f) { return std::fclose(f); });
  struct stat st {};
  if (::fstat(fileno(in), &st) == 0 && S_ISDIR(st.st_mode)) {
    throw InputError(SourcePos{opt.input}, "is a directory, not a capture file");
  }

  protocol::Decoder decoder(code);
  protocol::FrameJsonWriter json;
  const auto print = [&json](const protocol::DecodedFrame& f) {
    const auto line = json.line(f);
    std::fwrite(line.data(), 1, line.size(), stdout);
    std::fputc('\n', stdout);
  };
  std::vector<std::uint8_t> chunk(std::size_t{64} * 1024);
  while (true) {
    const std::size_t got = std::fread(chunk.data(), 1, chunk.size(), in);
    if (got > 0) decoder.push(std::span(chunk.data(), got), print);
    if (got < chunk.size()) {
      if (std::ferror(in)) {
        throw RuntimeError(opt.input + ": read error: " + std::strerror(errno));
      }
      break;
    }
  }
  decoder.finish();
  std::fflush(stdout);
  const auto& s = decoder.stats();
  std::fprintf(stderr,
               "frames: %llu, valid: %llu, bad checksum: %llu, invalid: %llu, bytes skipped: %llu "
               "(of %llu)\n",
               static_cast<unsigned long long>(s.frames), static_cast<unsigned long long>(s.valid),
               static_cast<unsigned long long>(s.bad_checksum), static_cast<unsigned long long>(s.invalid),
               static_cast<unsigned long long>(s.bytes_skipped), static_cast<unsigned long long>(s.bytes_total));
  return kExitOk;
}

void run_signals(bool as_json) {
  for (const auto& sig : protocol::kSignals) {
    const std::string name(sig.name), kind(to_string(sig.kind)), partner(sig.partner), label(sig.label);
    if (as_json) {
      nlohmann::ordered_json row;
      row["name"] = name;
      row["byte"] = sig.byte;
      row["bit"] = sig.is_bit() ? nlohmann::ordered_json(sig.bit) : nlohmann::ordered_json(nullptr);
      row["kind"] = kind;
      row["partner"] = sig.partner.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(partner);
      row["label"] = label;
      std::printf("%s\n", row.dump().c_str());
    } else {
      const std::string bit = sig.is_bit() ? std::to_string(sig.bit) : "0-7";
      std::printf("%-20s byte %2d bit %-3s %-10s %-20s %s\n", name.c_str(), sig.byte, bit.c_str(), kind.c_str(),
                  partner.empty() ? "-" : partner.c_str(), label.c_str());
    }
  }
}

}  // namespace

void add_frame_command(CLI::App& app, int& exit_code) {
  auto* frame = app.add_subcommand("frame", "Encode or decode switchbox frames (the reference codec)");
  frame->require_subcommand(1);

  auto enc = std::make_shared<EncodeOptions>();
  auto* encode_cmd = frame->add_subcommand("encode",
                                           "Print the 36-byte frame for 16 data bytes, as 72 upper-case hex digits.\n"
                                           "Encodes exactly what it is given: no bits are fixed.");
  encode_cmd->add_option("HEX32", enc->hex, "16 data bytes as 32 hex digits (spaces allowed)")->required();
  encode_cmd->add_flag("--raw", enc->raw, "write the 36 bytes themselves instead of hex text");
  encode_cmd->callback([enc] { run_encode(*enc); });

  auto dec = std::make_shared<DecodeOptions>();
  auto* decode_cmd =
      frame->add_subcommand("decode",
                            "Find every frame in a raw byte stream (a capture of the serial line) and print one\n"
                            "JSON object per frame per line; a summary goes to stderr.");
  decode_cmd->add_option("FILE", dec->input, "capture file, or - for standard input")->default_str("-");
  decode_cmd->add_option("--code", dec->code, "also flag frames whose byte 11 differs from this code (2 hex digits)");
  decode_cmd->callback([dec, &exit_code] { exit_code = run_decode(*dec); });

  auto as_json = std::make_shared<bool>(false);
  auto* signals_cmd =
      frame->add_subcommand("signals",
                            "List every signal of the frame under its canonical name: byte, bit, kind (motion,\n"
                            "selector, weapon, interlock, centred, level, constant), opposing partner, ICD wording.");
  signals_cmd->add_flag("--json", *as_json, "one JSON object per signal per line");
  signals_cmd->callback([as_json] { run_signals(*as_json); });
}

}  // namespace andros::cli
