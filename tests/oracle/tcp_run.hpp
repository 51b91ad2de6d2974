#pragma once
// One TCP run of the fault simulation (docs/testing.md, "Fault simulation": the TCP runs): a
// script through replay, the run loop on its virtual clock, whose link is
// the real TcpLink (and its ReconnectingLink) over the scripted server
// (tcp_server.hpp) instead of the sink; the server's oracle checks what it
// was sent. The script's link events are the server's, not the loop's.

#include <cstdint>
#include <exception>
#include <memory>
#include <string>
#include <vector>

#include "andros/base/clock.hpp"
#include "andros/base/text_file.hpp"
#include "andros/input/script_player.hpp"
#include "andros/link/tcp_link.hpp"
#include "andros/run/replay.hpp"
#include "oracle/simulation.hpp"
#include "oracle/tcp_server.hpp"

namespace andros::test {

/// The TCP link, with the server told the loop's time before each frame.
class ServerClockLink final : public link::Link {
 public:
  ServerClockLink(link::Link& inner, ScriptedServer& server) : inner_(inner), server_(server) {}
  link::SendResult send(const protocol::Frame& frame, std::int64_t now_ns) override {
    server_.at(now_ns / kNsPerMs);
    return inner_.send(frame, now_ns);
  }
  bool drain_and_close(int timeout_ms) override { return inner_.drain_and_close(timeout_ms); }
  [[nodiscard]] link::LinkState state() const override { return inner_.state(); }
  [[nodiscard]] const std::string& name() const override { return inner_.name(); }
  [[nodiscard]] const std::string& detail() const override { return inner_.detail(); }
  [[nodiscard]] const link::LinkCounters& counters() const override { return inner_.counters(); }
  [[nodiscard]] bool far_end_reading() const override { return inner_.far_end_reading(); }

 private:
  link::Link& inner_;
  ScriptedServer& server_;
};

struct TcpOutcome {
  std::string violation;  ///< empty: the server was sent nothing against the rules
  TcpCoverage coverage;
};

/// Replays script through mapping_file to the scripted server, with `--code` code.
inline TcpOutcome simulate_tcp(
    MappingCache& mappings, const std::string& mapping_file, const std::vector<input::InputEvent>& script,
    std::uint8_t code, const run::Bridge::Observer& observe = [](const run::TickReport&) {}) {
  std::vector<input::InputEvent> operator_events;
  for (const auto& e : script) {
    if (!ScriptedServer::is_server_event(e.type)) operator_events.push_back(e);
  }
  const std::string text = script_text(operator_events);
  TextReader in(text, "tcp.events", kEventScriptLimits);
  input::ScriptPlayer player(in);
  auto socket = std::make_unique<ScriptedServer>(script, code);
  ScriptedServer& server = *socket;
  // The drain at a suspend or the end waits on a clock of its own: the loop's time does not move for it, as for
  // replay's sink.
  VirtualClock drain_clock;
  link::TcpLink tcp("tcp scripted server", std::move(socket), &drain_clock);
  ServerClockLink link(tcp, server);
  run::ReplayOptions options{.engine = {false, parse_code(code_text(code), SourcePos{"--code"})}};
  options.load = [&mappings](const std::string& file) { return mappings.load(file); };
  options.observe = observe;
  options.link = &link;
  TcpOutcome out;
  try {
    run::replay(player, mapping::Engine(mappings.load(mapping_file), options.engine), options,
                [](std::int64_t, const protocol::DataBytes&) {});
  } catch (const std::exception& e) {
    out.violation = std::string("replay threw: ") + e.what();
  }
  if (out.violation.empty()) out.violation = server.violation();
  out.coverage = server.coverage();
  return out;
}

}  // namespace andros::test
