#include "andros/trainer/trainer_server.hpp"

#include <httplib.h>
#include <sys/socket.h>

#include <cerrno>
#include <charconv>
#include <cstring>
#include <thread>
#include <vector>

namespace andros::trainer {
namespace {

/// Threads beyond the event streams: the page and /state, short requests.
constexpr std::size_t kSpareThreads = 4;
constexpr int kMaxPort = 65535;
constexpr int kStartPolls = 2000;  ///< 1 ms each: the server's thread is running within 2 s

/// What every answer carries: nothing of it may be framed, sniffed or cached,
/// and the page may reach only this server.
void common_headers(httplib::Response& res) {
  res.set_header("Cache-Control", "no-store");
  res.set_header("X-Content-Type-Options", "nosniff");
  res.set_header("X-Frame-Options", "DENY");
  res.set_header("Content-Security-Policy",
                 "default-src 'none'; script-src 'unsafe-inline'; style-src 'unsafe-inline'; "
                 "connect-src 'self'; img-src data:; frame-ancestors 'none'");
}

void refuse(httplib::Response& res, int status, const std::string& why) {
  res.status = status;
  res.set_content(why + "\n", "text/plain; charset=utf-8");
  common_headers(res);
}

}  // namespace

ListenAddress parse_listen(std::string_view text, const SourcePos& pos) {
  const auto colon = text.rfind(':');
  if (colon == std::string_view::npos || colon == 0) {
    throw InputError(pos, "'" + std::string(text) + "' is not ADDR:PORT (e.g. 127.0.0.1:8037)");
  }
  const auto host = text.substr(0, colon);
  const auto port_text = text.substr(colon + 1);
  int port = 0;
  const auto [end, ec] = std::from_chars(port_text.data(), port_text.data() + port_text.size(), port);
  if (ec != std::errc() || end != port_text.data() + port_text.size() || port < 1 || port > kMaxPort) {
    throw InputError(pos, "'" + std::string(port_text) + "' is not a port (1..65535)");
  }
  for (const char c : host) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' || c == '-';
    if (!ok) throw InputError(pos, "'" + std::string(host) + "' is not an IPv4 address or a host name");
  }
  return ListenAddress{std::string(host), port};
}

struct TrainerServer::Impl {
  explicit Impl(StreamHub& h) : hub(h) {}
  StreamHub& hub;
  std::vector<std::string> paths{"/", "/state", "/events"};  ///< what is served, for a 404's text
  httplib::Server server;
  std::thread thread;
};

TrainerServer::TrainerServer(ServerOptions options, StreamHub& hub, std::string_view page, StateText state)
    : options_(std::move(options)), impl_(std::make_unique<Impl>(hub)) {
  auto& s = impl_->server;
  const std::size_t threads = hub.limits().max_clients + kSpareThreads;
  s.new_task_queue = [threads] { return new httplib::ThreadPool(threads); };
  // SO_REUSEADDR only: httplib's default adds SO_REUSEPORT, which would let
  // a second trainer share the port (and half the connections) unnoticed.
  s.set_socket_options([](socket_t sock) {
    int yes = 1;
    setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  });
  s.set_keep_alive_max_count(1);
  s.set_read_timeout(std::chrono::seconds(2));
  s.set_write_timeout(options_.write_timeout);
  s.set_payload_max_length(0);

  // The address as bound (start() learns the port when it is any): set before the server's thread starts.
  s.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
    const std::string host = options_.listen.host_header();
    if (req.method != "GET") {
      res.set_header("Allow", "GET");
      refuse(res, 405, "the trainer takes no commands: GET only");
      return httplib::Server::HandlerResponse::Handled;
    }
    // DNS rebinding: a page elsewhere whose name now points here still sends its own name.
    if (req.get_header_value("Host") != host) {
      refuse(res, 403, "Host must be " + host);
      return httplib::Server::HandlerResponse::Handled;
    }
    return httplib::Server::HandlerResponse::Unhandled;
  });
  s.set_error_handler([this](const httplib::Request&, httplib::Response& res) {
    if (res.status != 404) return;
    std::string served;
    for (const auto& p : impl_->paths) served += (served.empty() ? "" : ", ") + p;
    refuse(res, 404, "not here: " + served + " only");
  });
  s.Get("/", [page](const httplib::Request&, httplib::Response& res) {
    res.set_content(page.data(), page.size(), "text/html; charset=utf-8");
    common_headers(res);
  });
  if (!state) state = [&hub] { return hub.latest(); };
  s.Get("/state", [state](const httplib::Request&, httplib::Response& res) {
    auto latest = state();
    res.set_content(latest.empty() ? "{}" : latest, "application/json");
    common_headers(res);
  });
  const auto keepalive = options_.keepalive;
  s.Get("/events", [&hub, keepalive](const httplib::Request&, httplib::Response& res) {
    std::shared_ptr<Subscription> sub = hub.subscribe();
    if (!sub) {
      refuse(res, 503, "at most " + std::to_string(hub.limits().max_clients) + " event streams at once");
      return;
    }
    common_headers(res);
    res.set_chunked_content_provider("text/event-stream", [sub, keepalive](std::size_t, httplib::DataSink& sink) {
      const auto messages = sub->next(keepalive);
      if (!messages) return false;  // dropped, or the server is stopping
      std::string out = messages->empty() ? ": quiet\n\n" : "";
      for (const auto& m : *messages) out += "data: " + *m + "\n\n";
      return sink.write(out.data(), out.size());
    });
  });
}

void TrainerServer::add_json(const std::string& path, JsonQuery query) {
  impl_->paths.push_back(path);
  impl_->server.Get(path, [query = std::move(query)](const httplib::Request& req, httplib::Response& res) {
    const Params params(req.params.begin(), req.params.end());
    std::string why;
    if (auto body = query(params, &why)) {
      res.set_content(*body, "application/json");
      common_headers(res);
    } else {
      refuse(res, 400, why);
    }
  });
}

TrainerServer::~TrainerServer() { stop(); }

bool TrainerServer::start(std::string* why) {
  auto& a = options_.listen;
  errno = 0;
  bool bound = false;
  if (a.port == 0) {
    // Any free port (the tests'): the Host check then names the one taken.
    const int port = impl_->server.bind_to_any_port(a.host);
    bound = port > 0;
    if (bound) a.port = port;
  } else {
    bound = impl_->server.bind_to_port(a.host, a.port);
  }
  if (!bound) {
    *why = "cannot listen on " + a.host_header() + (errno != 0 ? std::string(": ") + std::strerror(errno) : "");
    return false;
  }
  impl_->thread = std::thread([this] { impl_->server.listen_after_bind(); });
  pthread_setname_np(impl_->thread.native_handle(), "andros-trainer");
  // Until its thread runs, httplib's stop() does nothing and the thread would
  // then listen for ever: a stop() right after start() must find it running.
  for (int i = 0; i < kStartPolls && !impl_->server.is_running(); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return true;
}

void TrainerServer::stop() {
  if (!impl_->thread.joinable()) return;
  impl_->hub.close();  // the streams end, and with them their threads, which stop() waits for
  impl_->server.stop();
  impl_->thread.join();
}

}  // namespace andros::trainer
