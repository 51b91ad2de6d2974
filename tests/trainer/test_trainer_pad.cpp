// Issue 37's acceptance: with a pad, the trainer's page follows the pad within
// one frame. `andros-bridge trainer --input sdl` runs in this process (a
// virtual device lives inside the process that made it), SDL's virtual pad is
// the operator's, and the test reads GET /events as the page does. Judged by
// the loop's ticks, never by the clock: a change the loop read at a tick shows
// in the vehicle on the page by the object sent during that tick or the next.
#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <poll.h>
#include <pthread.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "andros/input/sdl_input.hpp"
#include "cli/program.hpp"
#include "support/temp_dir.hpp"
#include "support/virtual_device.hpp"

namespace andros::trainer {
namespace {

using nlohmann::json;
using test::VirtualDevice;

int free_port() {
  const int fd = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  socklen_t size = sizeof a;
  bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a);
  getsockname(fd, reinterpret_cast<sockaddr*>(&a), &size);
  close(fd);
  return ntohs(a.sin_port);
}

/// GET /events as the page reads it: one JSON object per `data:` line.
class EventStream {
 public:
  /// Connects once the trainer listens (bounded: 10 s of tries).
  explicit EventStream(int port) {
    for (int i = 0; i < 100 && fd_ < 0; ++i) {
      const int fd = socket(AF_INET, SOCK_STREAM, 0);
      sockaddr_in a{};
      a.sin_family = AF_INET;
      a.sin_port = htons(static_cast<std::uint16_t>(port));
      a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
      if (connect(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0) {
        fd_ = fd;
      } else {
        close(fd);
        poll(nullptr, 0, 100);
      }
    }
    const std::string request =
        "GET /events HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port) + "\r\nAccept: text/event-stream\r\n\r\n";
    if (fd_ >= 0) {
      EXPECT_EQ(write(fd_, request.data(), request.size()), ssize_t(request.size()));
    }
  }
  ~EventStream() {
    if (fd_ >= 0) close(fd_);
  }
  EventStream(const EventStream&) = delete;
  EventStream& operator=(const EventStream&) = delete;

  [[nodiscard]] bool connected() const { return fd_ >= 0; }

  /// The objects until the first for which `done` holds (that one last),
  /// bounded at `most` objects; empty when the stream ended first.
  std::vector<json> until(const std::function<bool(const json&)>& done, int most = 500) {
    std::vector<json> seen;
    while (static_cast<int>(seen.size()) < most) {
      auto object = next();
      if (!object) break;
      seen.push_back(*object);
      if (done(*object)) return seen;
    }
    ADD_FAILURE() << "not seen in " << seen.size()
                  << " objects; the last: " << (seen.empty() ? "none" : seen.back().dump());
    return {};
  }

 private:
  std::optional<json> next() {
    for (int waited = 0; waited < 100;) {
      if (const auto end = got_.find('\n', pos_); end != std::string::npos) {
        const auto line = got_.substr(pos_, end - pos_);
        pos_ = end + 1;
        if (line.starts_with("data: ")) return json::parse(line.substr(6));
        continue;
      }
      pollfd p{fd_, POLLIN, 0};
      if (poll(&p, 1, 100) == 0) {
        ++waited;
        continue;
      }
      char buf[8192];
      const auto n = read(fd_, buf, sizeof buf);
      if (n <= 0) return std::nullopt;
      got_.append(buf, static_cast<std::size_t>(n));
    }
    return std::nullopt;
  }

  int fd_ = -1;
  std::string got_;
  std::size_t pos_ = 0;
};

/// `andros-bridge trainer` on a thread of this process; ended as Ctrl-C ends
/// it (a SIGINT, sent to that thread, which blocks and takes it).
class TrainerRun {
 public:
  explicit TrainerRun(std::vector<std::string> args) : args_(std::move(args)) {
    thread_ = std::thread([this] {
      std::vector<char*> argv;
      for (auto& a : args_) argv.push_back(a.data());
      exit_code_ = cli::program_main(static_cast<int>(argv.size()), argv.data());
    });
  }
  ~TrainerRun() { end(); }
  TrainerRun(const TrainerRun&) = delete;
  TrainerRun& operator=(const TrainerRun&) = delete;

  int end() {
    if (thread_.joinable()) {
      pthread_kill(thread_.native_handle(), SIGINT);
      thread_.join();
    }
    return exit_code_;
  }

 private:
  std::vector<std::string> args_;
  std::thread thread_;
  int exit_code_ = -1;
};

bool holds(const json& object, const char* button) {
  const auto& held = object["pad"]["buttons"];
  return std::find(held.begin(), held.end(), button) != held.end();
}

/// How far the page is behind the pad, in the loop's ticks: each object
/// carries the tick the loop had last finished when it was sent (the loop
/// sends one frame a tick, and each frame the vehicle decodes sends one
/// object). The pad's change first shows at the tick that read it; the
/// vehicle's answer is in the object sent during that tick or the next (a
/// motion shows once the vehicle has moved for a frame).
struct Lag {
  std::int64_t pad_tick = -1;
  std::int64_t effect_tick = -1;
  [[nodiscard]] std::int64_t ticks() const { return effect_tick - pad_tick; }
};

Lag lag(EventStream& events, const std::function<bool(const json&)>& seen,
        const std::function<bool(const json&)>& effect) {
  Lag out;
  for (const auto& o : events.until([&](const json& o) { return seen(o) && effect(o); })) {
    if (out.pad_tick < 0 && seen(o)) out.pad_tick = o["tick"];
    if (out.effect_tick < 0 && effect(o)) out.effect_tick = o["tick"];
  }
  return out;
}

TEST(TrainerPad, ThePageFollowsThePadWithinOneFrame) {
  test::use_dummy_video();
  input::SdlSession sdl;  // the virtual pad is attached before the trainer looks for one
  auto pad = VirtualDevice::pad("Trainer Pad");
  testing::TempDir home;
  setenv("XDG_CONFIG_HOME", (home.path() / "config").c_str(), 1);  // no user config file
  const int port = free_port();
  TrainerRun trainer({"andros-bridge", "trainer", "--input", "sdl", "--port", "sim", "--no-record", "--mapping",
                      std::string(ANDROS_MAPPINGS_DIR) + "/hd1.yaml", "--listen", "127.0.0.1:" + std::to_string(port)});
  EventStream events(port);
  ASSERT_TRUE(events.connected());
  events.until([](const json& o) { return o["pad"]["connected"] == true && o["frames"] > 5; });

  // The deadman (hd1: leftshoulder) pressed: enabled, and the frame's safety bit on.
  pad.button(SDL_CONTROLLER_BUTTON_LEFTSHOULDER, true);
  const auto enable = lag(
      events, [](const json& o) { return holds(o, "leftshoulder"); },
      [](const json& o) { return o["safety"] == true; });
  EXPECT_LE(enable.ticks(), 1) << "pressed at tick " << enable.pad_tick << ", enabled at " << enable.effect_tick;

  // The left stick forward (hd1: drive): the vehicle moves.
  pad.axis(SDL_CONTROLLER_AXIS_LEFTY, -32768);
  const auto drive = lag(
      events, [](const json& o) { return o["pad"]["axes"]["lefty"] == -32768; },
      [](const json& o) { return o["speed"] > 0.0; });
  EXPECT_LE(drive.ticks(), 1) << "pushed at tick " << drive.pad_tick << ", moving at " << drive.effect_tick;

  // Let go: the deadman's release stops it within a frame as well.
  pad.button(SDL_CONTROLLER_BUTTON_LEFTSHOULDER, false);
  const auto release = lag(
      events, [](const json& o) { return !holds(o, "leftshoulder"); },
      [](const json& o) { return o["safety"] == false && o["speed"] == 0.0; });
  EXPECT_LE(release.ticks(), 1) << "released at tick " << release.pad_tick << ", stopped at " << release.effect_tick;

  EXPECT_EQ(trainer.end(), 0);
}

}  // namespace
}  // namespace andros::trainer
