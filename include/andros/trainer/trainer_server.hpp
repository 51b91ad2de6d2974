#pragma once
/// The trainer's web server (docs/trainer.md): the page, the latest state
/// and the event stream, read-only, on a thread of its own. It listens on
/// 127.0.0.1 unless told otherwise, answers only a Host that names the
/// address it listens on (DNS rebinding), serves only what is embedded in
/// the binary (no request path reaches the file system), takes at most the
/// hub's max_clients streams, and drops a client that falls a queue behind.
/// Its failure (a port taken) never stops driving: start() says why, and the
/// trainer drives on without a page.

#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "andros/base/error.hpp"
#include "andros/trainer/stream_hub.hpp"

namespace andros::trainer {

/// The trainer's port unless --listen says otherwise (issue 37's number).
inline constexpr int kDefaultPort = 8037;
inline constexpr std::string_view kLoopback = "127.0.0.1";

struct ListenAddress {
  std::string host{kLoopback};
  int port = kDefaultPort;

  [[nodiscard]] bool loopback() const { return host == kLoopback; }
  /// What a browser sends as Host for it: "127.0.0.1:8037".
  [[nodiscard]] std::string host_header() const { return host + ":" + std::to_string(port); }
  [[nodiscard]] std::string url() const { return "http://" + host_header() + "/"; }
};

/// "ADDR:PORT" (an IPv4 address or a name, a port 1..65535); throws
/// InputError at pos for anything else.
ListenAddress parse_listen(std::string_view text, const SourcePos& pos);

struct ServerOptions {
  ListenAddress listen;
  /// A client whose socket takes no bytes for this long is let go (its thread freed).
  std::chrono::milliseconds write_timeout{2000};
  /// How often a quiet stream sends a comment line, to find a client gone.
  std::chrono::milliseconds keepalive{1000};
};

class TrainerServer {
 public:
  /// What GET /state answers (the hub's latest message when empty).
  using StateText = std::function<std::string()>;

  /// page: the HTML served at /, kept by the caller for the server's life.
  TrainerServer(ServerOptions options, StreamHub& hub, std::string_view page, StateText state = {});
  ~TrainerServer();
  TrainerServer(const TrainerServer&) = delete;
  TrainerServer& operator=(const TrainerServer&) = delete;

  /// A query's parameters (`?t=1.5`), as the request gave them.
  using Params = std::multimap<std::string, std::string>;
  /// A JSON answer to a query; nullopt: the query is refused (400, with why in *why).
  using JsonQuery = std::function<std::optional<std::string>(const Params& params, std::string* why)>;
  /// One more read-only path answered with JSON (before start(): a session's replay, docs/trainer.md).
  void add_json(const std::string& path, JsonQuery query);

  /// Binds the address and serves on a thread of its own; false (and why
  /// in *why) when it cannot bind (a port taken, an address not here).
  bool start(std::string* why);
  /// Ends every stream and the thread (the destructor does too).
  void stop();
  [[nodiscard]] const ListenAddress& address() const { return options_.listen; }

 private:
  struct Impl;
  ServerOptions options_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace andros::trainer
