// Issue 37's acceptance: with a pad, the trainer's page follows the pad within
// one frame. `andros-bridge trainer --input sdl` runs in this process (a
// virtual device lives inside the process that made it), SDL's virtual pad is
// the operator's, and the test reads GET /events as the page does.
//
// Judged in frames, never by the clock: each object names the frame it is
// for (`frame`, the frames the vehicle decoded) and the frame the pad it
// shows was read for (`pad.frame`). A change the loop read for frame N is
// in the vehicle of the object for frame N (the safety bit, the speed), not
// before, and the pose the page draws moves by that speed over the time to
// the next frame. How late the threads run changes when the objects come
// and how far apart the frames arrive, not what the objects say.
#include <SDL.h>
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
#include <future>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
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

  /// Reads objects until `done` holds for one (true), or the stream ends or
  /// 1,000 objects go by (false). Every object is kept.
  bool until(const std::function<bool(const json&)>& done) {
    for (int i = 0; i < 1000; ++i) {
      auto object = next();
      if (!object) return false;
      seen_.push_back(*object);
      if (done(*object)) return true;
    }
    return false;
  }

  /// The objects read so far, in order.
  [[nodiscard]] const std::vector<json>& seen() const { return seen_; }

 private:
  /// The next object; nullopt when the stream ends or is silent for 10 s.
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
  std::vector<json> seen_;
};

/// `andros-bridge trainer` on a thread of this process, ended as Ctrl-C ends
/// it (a SIGINT sent to that thread, which blocks it and takes it). An SDL
/// thread, not a std::thread: SDL frees what it keeps for a thread (its
/// error text) when one of its own threads ends, and never for another.
class TrainerRun {
 public:
  explicit TrainerRun(std::vector<std::string> args) : args_(std::move(args)) {
    thread_ = SDL_CreateThread(&TrainerRun::main, "trainer", this);
    EXPECT_NE(thread_, nullptr) << SDL_GetError();
  }
  ~TrainerRun() { end(); }
  TrainerRun(const TrainerRun&) = delete;
  TrainerRun& operator=(const TrainerRun&) = delete;

  /// Ends the run; its exit code.
  int end() {
    if (thread_ != nullptr) {
      pthread_kill(id_.get_future().get(), SIGINT);
      SDL_WaitThread(thread_, &exit_code_);
      thread_ = nullptr;
    }
    return exit_code_;
  }

 private:
  static int main(void* data) {
    auto* self = static_cast<TrainerRun*>(data);
    self->id_.set_value(pthread_self());
    std::vector<char*> argv;
    for (auto& a : self->args_) argv.push_back(a.data());
    return cli::program_main(static_cast<int>(argv.size()), argv.data());
  }

  std::vector<std::string> args_;
  std::promise<pthread_t> id_;
  SDL_Thread* thread_ = nullptr;
  int exit_code_ = -1;
};

bool holds(const json& object, const char* button) {
  const auto& held = object["pad"]["buttons"];
  return std::find(held.begin(), held.end(), button) != held.end();
}

using Holds = std::function<bool(const json&)>;

/// The frames as the stream showed them: for each frame, its first object
/// (published when the vehicle took it; later ones for the same frame only
/// advance its time while no frame comes).
class Frames {
 public:
  explicit Frames(const std::vector<json>& seen) {
    for (const auto& o : seen) {
      if (o.contains("frame")) by_frame_.emplace(o["frame"].get<std::int64_t>(), o);
    }
  }

  /// The first frame read with the pad as `pad` says (pad.frame), from
  /// frame `from` on; -1 when none.
  [[nodiscard]] std::int64_t pad_read(std::int64_t from, const Holds& pad) const {
    std::int64_t first = -1;
    for (const auto& [frame, o] : by_frame_) {
      const auto read = o["pad"]["frame"].get<std::int64_t>();
      if (read >= from && pad(o) && (first < 0 || read < first)) first = read;
    }
    return first;
  }
  /// The first frame from `from` on whose vehicle `effect` says holds; -1 when none.
  [[nodiscard]] std::int64_t first(std::int64_t from, const Holds& effect) const {
    for (auto it = by_frame_.lower_bound(from); it != by_frame_.end(); ++it) {
      if (effect(it->second)) return it->first;
    }
    return -1;
  }
  /// Every frame from the first to the last has its object: none went unseen.
  [[nodiscard]] bool whole() const {
    return !by_frame_.empty() &&
           by_frame_.rbegin()->first - by_frame_.begin()->first + 1 == static_cast<std::int64_t>(by_frame_.size());
  }
  [[nodiscard]] const std::map<std::int64_t, json>& all() const { return by_frame_; }

 private:
  std::map<std::int64_t, json> by_frame_;
};

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
  ASSERT_TRUE(events.until([](const json& o) { return o["pad"]["connected"] == true && o["frame"] > 5; }));
  const std::int64_t start = events.seen().back()["frame"];

  // The deadman (hd1: leftshoulder) pressed: enabled, the frame's safety bit on.
  pad.button(SDL_CONTROLLER_BUTTON_LEFTSHOULDER, true);
  const Holds pressed = [](const json& o) { return holds(o, "leftshoulder"); };
  const Holds safety = [](const json& o) { return o["safety"] == true; };
  ASSERT_TRUE(events.until([&](const json& o) { return pressed(o) && safety(o); }));
  // The left stick full forward (hd1: drive): the vehicle drives off.
  pad.axis(SDL_CONTROLLER_AXIS_LEFTY, -32768);
  const Holds pushed = [](const json& o) { return o["pad"]["axes"]["lefty"] == -32768; };
  const Holds driving = [](const json& o) { return o["speed"] != 0.0; };
  ASSERT_TRUE(events.until([&](const json& o) { return pushed(o) && driving(o); }));
  ASSERT_TRUE(events.until([&, moving = events.seen().back()["frame"].get<std::int64_t>()](const json& o) {
    return o["frame"] >= moving + 3;
  }));
  // Let go of the deadman, the stick still forward: it stops.
  pad.button(SDL_CONTROLLER_BUTTON_LEFTSHOULDER, false);
  ASSERT_TRUE(events.until([&](const json& o) { return !pressed(o) && !safety(o); }));
  ASSERT_TRUE(events.until([&, stopped = events.seen().back()["frame"].get<std::int64_t>()](const json& o) {
    return o["frame"] >= stopped + 3;
  }));
  EXPECT_EQ(trainer.end(), 0);

  const Frames frames(events.seen());
  ASSERT_TRUE(frames.whole()) << "a frame without its object in the stream";
  const auto press = frames.pad_read(start, pressed);
  ASSERT_GT(press, start);
  const auto push = frames.pad_read(press, pushed);
  const auto release = frames.pad_read(push, [&](const json& o) { return !pressed(o); });
  // Each in the vehicle of the object for the frame the loop read it for: never before, and so within one frame.
  const auto enabled = frames.first(start, safety);
  EXPECT_EQ(enabled, press) << "deadman read for frame " << press << ", the safety bit first at frame " << enabled;
  const auto drives = frames.first(start, driving);
  EXPECT_EQ(drives, push) << "stick read for frame " << push << ", the speed first at frame " << drives;
  const auto stops = frames.first(push, [&](const json& o) { return !safety(o) && o["speed"] == 0.0; });
  EXPECT_EQ(stops, release) << "deadman released for frame " << release << ", stopped at frame " << stops;

  // The pose the page draws: each frame's object moved on from the frame
  // before's by that frame's speed over the time between their arrivals (at
  // most the vehicle's watchdog, 500 ms: docs/trainer.md), straight ahead
  // (no pivot). So the vehicle stands until the stick's frame, moves from
  // the next frame's object on, and stands again from the release's frame.
  constexpr double kWatchdogS = 0.5;
  constexpr double kRounding = 0.002;  // x to the mm, speed to the mm/s
  const auto& all = frames.all();
  for (auto before = all.begin(), here = std::next(before); here != all.end(); ++before, ++here) {
    const auto& b = before->second;
    const auto& h = here->second;
    const double dt = std::min(h["time"].get<double>() - b["time"].get<double>(), kWatchdogS);
    EXPECT_NEAR(h["pose"]["x"].get<double>() - b["pose"]["x"].get<double>(), b["speed"].get<double>() * dt, kRounding)
        << "frame " << here->first << ": " << b["pose"] << " at " << b["time"] << " s, then " << h["pose"] << " at "
        << h["time"] << " s";
    EXPECT_EQ(h["pose"]["y"], 0.0);
    EXPECT_EQ(h["pose"]["heading"], 0.0);
    if (here->first <= push) {
      EXPECT_EQ(h["pose"]["x"], 0.0) << "moved before the stick's frame, at frame " << here->first;
    }
    if (before->first >= release) {
      EXPECT_EQ(h["pose"], b["pose"]) << "moved after the release's frame, at frame " << here->first;
    }
  }
}

}  // namespace
}  // namespace andros::trainer
