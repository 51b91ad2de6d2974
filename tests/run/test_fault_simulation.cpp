// Deterministic fault simulation (docs/testing.md): random event scripts with
// faults (the controller lost and back, link flaps and take-overs, reloads
// of good, bad and missing mappings, suspend and resume, a stop; stop
// buttons on either pad and their resets, a deadman let go and pressed again
// or a trigger squeezed past its panic point within one frame) through
// replay, the run loop itself on a virtual clock, over every shipped mapping
// with weapons off and on. Every delivered frame is checked by
// tests/oracle/safety_oracle.hpp, which reads only the script and the frame
// bytes. A failure prints the seed and the whole script, and writes it where
// `andros-bridge replay` can play it again.
//
// The mappings are the simulation's own (tests/data/simulation/mappings/):
// every shipped robot's with a centre trim, an enable timeout and a
// supervisor's stop, and on every other seed a three-position trigger deadman
// with a panic point; on one seed in eight the engine is at fault from the
// middle of the script (the frame gate must refuse it); on one seed in eight
// a TCP run as well: a script of its own to the real TcpLink over a scripted
// server that stalls, resets and refuses (tcp_run.hpp, whose oracle checks
// what the server was sent); the oracle's own tests are in test_oracle.cpp.
//
// Seeds 1..10,000 (1,000 under the sanitizers: support/sweep.hpp; a build
// configured with -DANDROS_SIM_SCRIPTS=N runs N); the
// environment picks other ranges: ANDROS_SIM_SEED_BASE=N (the first seed),
// ANDROS_SIM_SCRIPTS=M (how many). ANDROS_SIM_MAX_REPORTED=K prints up to K
// failing seeds (5), ANDROS_SIM_TRACE=1 every tick of the loop,
// ANDROS_SIM_COUNT_ALL=1 runs every seed however many fail and says how many
// did (scripts/mutation_test.sh).
// ANDROS_SIM_THREADS=T runs the seeds on T threads (one per core, at most 4):
// seed s on thread s % T, each with its own mappings, the coverage and the
// failures gathered at the end, so that what is checked and printed does not
// depend on T (the sanitizer build's longest test, halved).
#include <gtest/gtest.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "andros/input/events.hpp"
#include "andros/mapping/loader.hpp"
#include "andros/protocol/robots.hpp"
#include "andros/run/replay.hpp"
#include "oracle/fault_script.hpp"
#include "oracle/random.hpp"
#include "oracle/safety_oracle.hpp"
#include "oracle/simulation.hpp"
#include "oracle/tcp_run.hpp"
#include "oracle/tcp_script.hpp"
#include "support/sweep.hpp"

namespace andros::run {
namespace {

#ifdef ANDROS_SIM_SCRIPTS
constexpr std::uint64_t kScripts = ANDROS_SIM_SCRIPTS;
#else
constexpr std::uint64_t kScripts = test::sweep_size(10'000, 500);
#endif

constexpr std::uint8_t kCode = 0x5A;

/// A seed's dip-switch code, over the whole byte (0x00..0xFF), apart from its mapping (a Fibonacci hash's top byte).
std::uint8_t code_of(std::uint64_t seed) { return static_cast<std::uint8_t>((seed * 0x9E3779B97F4A7C15ULL) >> 56U); }

/// The simulated HD1 (an enable timeout of 2 s): the TCP runs' and the replay tests' below.
const std::string kSimulationHd1 = ANDROS_TEST_DATA_DIR "/simulation/mappings/hd1.yaml";

/// Whether a seed has a TCP run as well (one in eight, apart from its engine fault): its own script
/// (tcp_script.hpp) to the real TcpLink over the scripted server (tcp_run.hpp).
bool tcp_run_of(std::uint64_t seed) { return ((seed * 0xD6E8FEB86659FD93ULL) >> 61U) == 0; }

/// A seed's engine fault (tests/support/faulty_frames.hpp), on one seed in
/// eight, apart from its mapping and code: one of the faults the frame gate
/// refuses, from the middle of the script on, in the run with weapons as the
/// fault asks (the other run as it is).
std::optional<test::FaultKind> fault_of(std::uint64_t seed) {
  if (((seed * 0xBF58476D1CE4E5B9ULL) >> 61U) != 0) return std::nullopt;
  return test::kFaultKinds[((seed * 0x94D049BB133111EBULL) >> 40U) % test::kFaultKinds.size()];
}

std::uint64_t from_environment(const char* name, std::uint64_t fallback) {
  const char* text = std::getenv(name);
  if (text == nullptr || *text == '\0') return fallback;
  char* end = nullptr;
  const auto value = std::strtoull(text, &end, 10);
  if (*end != '\0') throw std::invalid_argument(std::string(name) + "=" + text + ": not a whole number");
  return value;
}

// The mappings a simulation runs and reloads.
class Library : public test::MappingCache {
 public:
  Library() {
    for (const auto robot : protocol::kRobotTypes) {
      const auto file = mapping::find_robot_mapping(robot, {ANDROS_MAPPINGS_DIR});
      // The shipped mapping with a trim, a timeout and a supervisor's stop.
      const std::string own = ANDROS_TEST_DATA_DIR "/simulation/mappings/" + file.filename().string();
      buttons_.push_back(own);
      targets_.good.push_back(own);
      targets_.good.push_back(file.string());
    }
    // Issue 16's safety keys (a three-position trigger deadman, a stop button, an enable timeout), and
    // a trigger deadman with a trim and a supervisor's stop.
    for (const char* trigger : {"/mappings/safety.yaml", "/simulation/mappings/trigger.yaml"}) {
      triggers_.push_back(ANDROS_TEST_DATA_DIR + std::string(trigger));
      targets_.good.push_back(triggers_.back());
    }
    // HD1 with the supervisor's weapons consent (the two-person rule).
    const std::string consent = ANDROS_TEST_DATA_DIR "/simulation/mappings/consent.yaml";
    buttons_.push_back(consent);
    targets_.good.push_back(consent);
    // A layout whose weapons arm with RB, not LT, and one with another rest rule.
    targets_.good.push_back(ANDROS_TEST_DATA_DIR "/mappings/core.yaml");
    targets_.good.push_back(ANDROS_TEST_DATA_DIR "/mappings/rest.yaml");
    targets_.bad.push_back(ANDROS_MAPPINGS_DIR "/common.yaml");  // a base: no robot, refused
    targets_.bad.push_back(ANDROS_TEST_DATA_DIR "/mappings/missing.yaml");
  }

  /// A seed's mapping: a trigger deadman with a panic point on every other seed, a button on the rest.
  [[nodiscard]] const std::string& mapping_for(std::uint64_t seed) const {
    const auto& list = seed % 2 == 0 ? triggers_ : buttons_;
    return list[(seed / 2) % list.size()];
  }
  [[nodiscard]] const test::ReloadTargets& targets() const { return targets_; }

 private:
  std::vector<std::string> buttons_;
  std::vector<std::string> triggers_;
  test::ReloadTargets targets_;
};

// ANDROS_SIM_TRACE=1: every tick, the loop's state and what became of its frame.
void trace(const TickReport& r) {
  const auto s = protocol::read_signals(r.data);
  std::printf("%6lld %-13s %s safety=%d drive=%d\n", static_cast<long long>(r.t_ms),
              std::string(to_string(r.state)).c_str(),
              !r.sent                               ? "not offered"
              : r.result == link::SendResult::kSent ? "delivered  "
                                                    : "refused    ",
              s[protocol::signal_id("safety")], s[protocol::signal_id("drive")]);
}

/// What a failure prints: enough to play it again by hand.
std::string describe_failure(std::uint64_t seed, const std::string& mapping_file, bool weapons,
                             const std::vector<input::InputEvent>& script, const std::string& violation) {
  const std::string code = test::code_text(code_of(seed));
  const std::string name = "andros-sim-" + std::to_string(seed) + (weapons ? "-weapons" : "") + ".events";
  const std::filesystem::path saved = std::filesystem::path(::testing::TempDir()) / name;
  std::ofstream(saved) << test::script_text(script);
  return "seed " + std::to_string(seed) + ", " + mapping_file + (weapons ? ", --weapons" : "") + ": " + violation +
         "\nagain: ANDROS_SIM_SEED_BASE=" + std::to_string(seed) +
         " ANDROS_SIM_SCRIPTS=1 andros_simulation_tests, or\n"
         "       andros-bridge replay --mapping " +
         mapping_file + (weapons ? " --weapons" : "") + " --code " + code + " " + saved.string() + "\nthe script:\n" +
         test::script_text(script);
}

/// The same for a TCP run: the simulated HD1, the script's link events the server's (not replay's).
std::string describe_tcp_failure(std::uint64_t seed, const std::vector<input::InputEvent>& script,
                                 const std::string& violation) {
  return "seed " + std::to_string(seed) + ", its TCP run (the simulated HD1, --code " + test::code_text(code_of(seed)) +
         "; the link events are the scripted server's): " + violation +
         "\nagain: ANDROS_SIM_SEED_BASE=" + std::to_string(seed) +
         " ANDROS_SIM_SCRIPTS=1 andros_simulation_tests\nthe script:\n" + test::script_text(script);
}

TEST(FaultSimulation, RandomScriptsWithFaultsKeepTheSafetyRules) {
  const std::uint64_t first = from_environment("ANDROS_SIM_SEED_BASE", 1);
  const std::uint64_t count = from_environment("ANDROS_SIM_SCRIPTS", kScripts);
  const auto max_reported = from_environment("ANDROS_SIM_MAX_REPORTED", 5);  // failures printed before it gives up
  const bool tracing = from_environment("ANDROS_SIM_TRACE", 0) != 0;
  const bool count_all = from_environment("ANDROS_SIM_COUNT_ALL", 0) != 0;
  const Bridge::Observer observe = tracing ? trace : [](const TickReport&) {};
  const std::uint64_t cores = std::clamp<std::uint64_t>(std::thread::hardware_concurrency(), 1, 4);
  const std::uint64_t threads = tracing ? 1 : std::max<std::uint64_t>(1, from_environment("ANDROS_SIM_THREADS", cores));

  // One worker per thread: the seeds s with s % threads == k, in order, each
  // failure kept by seed; a worker stops after max_reported failures of its own.
  struct Worker {
    test::OracleCoverage coverage;
    test::TcpCoverage tcp;
    std::vector<std::pair<std::uint64_t, std::string>> failures;
    std::uint64_t failed = 0;  ///< seeds that broke a rule
  };
  std::vector<Worker> workers(threads);
  // The TCP runs' link logs each loss and reconnection, as in `run`: thousands of lines here, read by no one.
  struct Quiet {
    spdlog::level::level_enum was = spdlog::default_logger()->level();
    Quiet() { spdlog::default_logger()->set_level(spdlog::level::off); }
    ~Quiet() { spdlog::default_logger()->set_level(was); }
    Quiet(const Quiet&) = delete;
    Quiet& operator=(const Quiet&) = delete;
  } quiet;
  auto work = [&](std::uint64_t k) {
    Library library;
    Worker& w = workers[k];
    for (std::uint64_t seed = first + k; seed < first + count && (count_all || w.failures.size() < max_reported);
         seed += threads) {
      test::Random rng(seed);
      const auto script = test::fault_script(rng, library.targets());
      const std::string& mapping_file = library.mapping_for(seed);
      const auto fault = fault_of(seed);
      bool seed_failed = false;
      for (const bool weapons : {false, true}) {
        std::optional<test::InjectedFault> injected;
        if (fault && fault->weapons == weapons) injected = test::InjectedFault{fault->fault, script.back().t_ms / 2};
        const auto out = test::simulate(library, mapping_file, script, weapons, code_of(seed), observe, injected);
        w.coverage += out.coverage;
        if (!out.violation.empty()) {
          seed_failed = true;
          ++w.failed;
          if (w.failures.size() < max_reported) {
            const std::string at_fault = injected ? "the engine at fault (" + std::string(fault->name) +
                                                        ") from t=" + std::to_string(injected->from_ms) +
                                                        " (not in replay), "
                                                  : "";
            w.failures.emplace_back(seed,
                                    describe_failure(seed, mapping_file, weapons, script, at_fault + out.violation));
          }
          break;
        }
      }
      if (seed_failed || !tcp_run_of(seed)) continue;
      test::Random tcp_rng(~seed);
      const auto tcp_script = test::tcp_script(tcp_rng);
      const auto out = test::simulate_tcp(library, kSimulationHd1, tcp_script, code_of(seed), observe);
      w.tcp += out.coverage;
      if (out.violation.empty()) continue;
      ++w.failed;
      if (w.failures.size() < max_reported)
        w.failures.emplace_back(seed, describe_tcp_failure(seed, tcp_script, out.violation));
    }
  };
  std::vector<std::thread> running;
  for (std::uint64_t k = 1; k < threads; ++k) running.emplace_back(work, k);
  work(0);
  for (auto& t : running) t.join();

  test::OracleCoverage coverage;
  test::TcpCoverage tcp;
  std::vector<std::pair<std::uint64_t, std::string>> failed;
  std::uint64_t seeds_failed = 0;
  for (auto& w : workers) {
    coverage += w.coverage;
    tcp += w.tcp;
    seeds_failed += w.failed;
    failed.insert(failed.end(), w.failures.begin(), w.failures.end());
  }
  std::sort(failed.begin(), failed.end());
  if (failed.size() > max_reported) failed.resize(max_reported);
  for (const auto& [seed, text] : failed) ADD_FAILURE() << text;
  const std::uint64_t failures = failed.size();
  std::printf("fault simulation: %llu of %llu seeds broke a rule%s\n", static_cast<unsigned long long>(seeds_failed),
              static_cast<unsigned long long>(count),
              count_all || seeds_failed == 0 ? "" : " (at most the first few counted)");
  const std::uint64_t seed = failed.empty() ? first + count : failed.back().first + 1;
  std::string endings;
  for (std::size_t i = 0; i < coverage.motion_after.size(); ++i) {
    if (coverage.motion_after[i] == 0) continue;
    endings += (endings.empty() ? "" : ", ") + std::string(to_string(static_cast<test::Ending>(i))) + " " +
               std::to_string(coverage.motion_after[i]);
  }
  std::printf(
      "fault simulation: seeds %llu..%llu, %lld frames, %lld with motion (a fresh press after: %s), "
      "%lld with a weapon, %lld stops owed 3 frames, %lld suspend and %lld reload neutral frames, "
      "%lld stop-button latches (%lld supervisor's stop presses), %lld panic squeezes, %lld enable timeouts, "
      "%lld frames with a supervisor's controller; the frame gate checked %lld frames offered to the link and "
      "refused an engine at fault in %lld runs\n",
      static_cast<unsigned long long>(first), static_cast<unsigned long long>(seed - 1),
      static_cast<long long>(coverage.frames), static_cast<long long>(coverage.motion), endings.c_str(),
      static_cast<long long>(coverage.weapons), static_cast<long long>(coverage.stops_with_frames),
      static_cast<long long>(coverage.suspend_frames), static_cast<long long>(coverage.reload_frames),
      static_cast<long long>(coverage.stop_latches), static_cast<long long>(coverage.supervisor_stops),
      static_cast<long long>(coverage.panics), static_cast<long long>(coverage.timeouts),
      static_cast<long long>(coverage.supervised_frames), static_cast<long long>(coverage.gated),
      static_cast<long long>(coverage.gate_refused));
  std::printf(
      "fault simulation: %lld frames of a mapping with a centre trim, %lld enabled frames with drive or pivot "
      "held at it by the rest rule\n",
      static_cast<long long>(coverage.trimmed), static_cast<long long>(coverage.rest_held));
  std::printf(
      "fault simulation: %lld stops reset by the operator and %lld by the supervisor (%lld resets refused: the "
      "operator's of the supervisor's stop, or from a pad that did not stop)\n",
      static_cast<long long>(coverage.operator_resets), static_cast<long long>(coverage.supervisor_resets),
      static_cast<long long>(coverage.refused_resets));
  std::printf(
      "fault simulation, TCP runs: %lld frames to the scripted server, %lld with motion (%lld after a server that "
      "stalled read again); %lld connections reset as stalled, %lld neutral frames to a distrusted server; %lld "
      "connections ended by the server, %lld attempts refused, %lld after a back-off of 1 s or more\n",
      static_cast<long long>(tcp.frames), static_cast<long long>(tcp.motion), static_cast<long long>(tcp.motion_again),
      static_cast<long long>(tcp.stalls_dropped), static_cast<long long>(tcp.distrusted),
      static_cast<long long>(tcp.server_ends), static_cast<long long>(tcp.refused),
      static_cast<long long>(tcp.backoff_waited));
  if (failures > 0 || count < 1000) return;  // too few scripts to ask for everything below
  // The TCP runs reach the link's own rules: stalls dropped, a distrusted server sent neutral frames, motion once it
  // reads again, the server's resets and refusals, a back-off grown.
  for (const auto& [what, reached] : {std::pair{"motion", tcp.motion},
                                      {"stall dropped", tcp.stalls_dropped},
                                      {"frame to a distrusted server", tcp.distrusted},
                                      {"motion after reading again", tcp.motion_again},
                                      {"connection ended by the server", tcp.server_ends},
                                      {"attempt refused", tcp.refused},
                                      {"back-off of 1 s", tcp.backoff_waited}}) {
    EXPECT_GT(reached, 0) << "TCP runs: no " << what;
  }
  // The scripts reach what the rules are about: motion again after each kind
  // of fault (a fresh press after it), weapons, and the neutral frames owed.
  using test::Ending;
  for (const auto after : {Ending::kConnect, Ending::kLinkUp, Ending::kResume, Ending::kReloadSame, Ending::kReloadGood,
                           Ending::kReloadBad}) {
    EXPECT_GT(coverage.motion_after[static_cast<std::size_t>(after)], 0) << "no motion after a " << to_string(after);
  }
  EXPECT_GT(coverage.weapons, 0);
  EXPECT_GT(coverage.stops_with_frames, 0);
  EXPECT_GT(coverage.suspend_frames, 0);
  EXPECT_GT(coverage.reload_frames, 0);
  EXPECT_GT(coverage.stop_latches, 0);
  EXPECT_GT(coverage.panics, 0);
  EXPECT_GT(coverage.timeouts, 0);
  EXPECT_GT(coverage.supervisor_stops, 0);
  EXPECT_GT(coverage.supervised_frames, 0);
  EXPECT_GT(coverage.gated, coverage.frames);  // the gate saw every frame, those the link refused too
  EXPECT_GT(coverage.gate_refused, 0);
  EXPECT_GT(coverage.trimmed, coverage.frames / 2);
  EXPECT_GT(coverage.rest_held, 0);
  EXPECT_GT(coverage.operator_resets, 0);
  EXPECT_GT(coverage.supervisor_resets, 0);
  EXPECT_GT(coverage.refused_resets, 0);
  // After a stop, motion comes only after its reset (the last interruption before the press is the reset).
  for (const auto after : {Ending::kReset, Ending::kPanic, Ending::kTimeout}) {
    EXPECT_GT(coverage.motion_after[static_cast<std::size_t>(after)], 0) << "no motion after a " << to_string(after);
  }
}

// What the simulation once missed (issue 35), each a script through the
// simulation with the simulated mappings' HD1 (an enable timeout of 2 s):
// frames are checked by the oracle, and what must still drive is asked for.

struct Played {
  std::string violation;
  std::vector<std::int64_t> enabled;                      ///< the ticks whose frame the link took with safety = 1
  std::map<std::int64_t, protocol::ControlState> frames;  ///< each frame the link took, by its tick
};
Played play(const std::string& text, std::uint8_t code = kCode, const std::string& mapping_file = kSimulationHd1,
            bool weapons = false) {
  Library library;
  Played p;
  const auto script = input::parse_event_script(text, "issue35.events");
  const auto out = test::simulate(library, mapping_file, script, weapons, code, [&p](const TickReport& r) {
    if (!r.sent || r.result != link::SendResult::kSent) return;
    if (r.enabled()) p.enabled.push_back(r.t_ms);
    p.frames[r.t_ms] = protocol::read_signals(r.data);
  });
  p.violation = out.violation;
  return p;
}

/// The first tick at or after t whose frame was enabled; -1: none.
std::int64_t first_enabled_from(const Played& p, std::int64_t t) {
  const auto it = std::find_if(p.enabled.begin(), p.enabled.end(), [t](std::int64_t u) { return u >= t; });
  return it == p.enabled.end() ? -1 : *it;
}

/// The script kept every rule, drove before t and never from t on.
void expect_driving_only_before(const Played& p, std::int64_t t) {
  EXPECT_EQ(p.violation, "");
  ASSERT_FALSE(p.enabled.empty());
  EXPECT_LT(p.enabled.back(), t);
}

// A deadman wedged down and the stick jittering 60 every 100 ms: noise within
// the 1024 band, so "enabled" ends 2 s after the last change (seen at 80: the
// frame at 2080 is neutral); a hand moving 2,200 drives on.
std::string jittering(int size) {
  std::string text = "0 connect\n20 button leftshoulder 1\n60 axis lefty -20000\n";
  for (int t = 160, sign = 1; t <= 3900; t += 100, sign = -sign) {
    text += std::to_string(t) + " axis lefty " + std::to_string(-20000 + sign * size) + "\n";
  }
  return text + "4000 end\n";
}

TEST(FaultSimulation, PadNoiseWithinTheBandDoesNotHoldOffTheEnableTimeout) {
  const auto noise = play(jittering(30));
  EXPECT_EQ(noise.violation, "");
  ASSERT_FALSE(noise.enabled.empty());
  EXPECT_EQ(noise.enabled.back(), 2040);
  const auto hand = play(jittering(1100));
  EXPECT_EQ(hand.violation, "");
  ASSERT_FALSE(hand.enabled.empty());
  EXPECT_EQ(hand.enabled.back(), 4000);
}

// A TCP server that stops reading gets neutral frames only, through fresh
// deadman presses, a reset and the link reopened, until it is seen reading;
// then a fresh press drives again.
TEST(FaultSimulation, AStalledLinkGetsNoMotionThroughFreshPressesAndResets) {
  const auto p = play(
      "0 connect\n20 button leftshoulder 1\n60 axis lefty -32768\n200 link stalled\n"
      "300 button leftshoulder 0\n340 button leftshoulder 1\n500 button leftshoulder 0\n540 button leftshoulder 1\n"
      "600 link down\n700 link up\n800 button leftshoulder 0\n840 button leftshoulder 1\n1000 link reading\n"
      "1100 button leftshoulder 0\n1140 button leftshoulder 1\n1200 axis lefty 0\n1240 axis lefty -32768\n"
      "1400 end\n");
  EXPECT_EQ(p.violation, "");
  ASSERT_FALSE(p.enabled.empty());
  EXPECT_LT(p.enabled.front(), 200);
  EXPECT_EQ(first_enabled_from(p, 200), 1160);  // the first tick after the fresh press once it reads again
}

// The same against the real TcpLink over the scripted server (tcp_run.hpp;
// issue 35's second survivor): a server that stops reading at 1000 is reset
// as stalled once 19 frames wait unread (from 1680) and its window stays
// still for 2 s (at 3680); the connection after it (at 3960) gets neutral
// frames only, through a fresh deadman press every 300 ms, until the server
// reads again at 5800; then a fresh press drives again.
TEST(FaultSimulation, AStalledTcpServerGetsNoMotionThroughFreshPresses) {
  Library library;
  std::string text = "0 connect\n20 button leftshoulder 1\n60 axis lefty -32768\n1000 link stalled\n";
  for (int t = 1300; t < 5700; t += 300) {
    text += std::to_string(t) + " button leftshoulder 0\n" + std::to_string(t + 40) + " button leftshoulder 1\n";
  }
  text += "5800 link reading\n6100 button leftshoulder 0\n6140 button leftshoulder 1\n6500 end\n";
  std::vector<std::int64_t> driving;  // the ticks whose frame the link took with safety = 1
  const auto out = test::simulate_tcp(library, kSimulationHd1, input::parse_event_script(text, "tcp.events"), kCode,
                                      [&driving](const TickReport& r) {
                                        if (r.delivered() && r.enabled()) driving.push_back(r.t_ms);
                                      });
  EXPECT_EQ(out.violation, "");
  EXPECT_EQ(out.coverage.stalls_dropped, 1);
  EXPECT_GT(out.coverage.distrusted, 10);
  const auto after_drop = std::find_if(driving.begin(), driving.end(), [](std::int64_t t) { return t > 3800; });
  ASSERT_NE(after_drop, driving.end());
  EXPECT_EQ(*after_drop, 6160);  // the first tick after the fresh press once it reads again
}

// A server that resets its connection at 500 and refuses new ones until 5500:
// the attempts come 250 ms after the link meets the reset (its frame at 520),
// then 500, 1000, 2000 and 4000 ms after each refusal (docs/running.md): at
// 800, 1320, 2320 and 4320 refused, at 8320 taken. That connection, reset at
// 9000 (up for less than 5 s), waits 4 s more: back at 13000; the next, reset
// at 18500 (up for more than 5 s; its frame at 18520 meets the reset),
// starts again at 250 ms: back at 18800.
TEST(FaultSimulation, ATcpServerThatRefusesIsRetriedWithBackOff) {
  Library library;
  std::vector<std::int64_t> taken;
  const auto out = test::simulate_tcp(library, kSimulationHd1,
                                      input::parse_event_script("0 connect\n500 link down\n5500 link up\n"
                                                                "9000 link down\n9100 link up\n18500 link down\n"
                                                                "18600 link up\n19000 end\n",
                                                                "tcp.events"),
                                      kCode, [&taken](const TickReport& r) {
                                        if (r.delivered()) taken.push_back(r.t_ms);
                                      });
  EXPECT_EQ(out.violation, "");
  EXPECT_EQ(out.coverage.refused, 4);
  const auto back_after = [&taken](std::int64_t t) {
    const auto it = std::find_if(taken.begin(), taken.end(), [t](std::int64_t u) { return u > t; });
    return it == taken.end() ? -1 : *it;
  };
  EXPECT_EQ(back_after(520), 8320);
  EXPECT_EQ(back_after(9000), 13000);
  EXPECT_EQ(back_after(18500), 18800);
}

// Every dip-switch code, 0x00 to 0xFF, given as `--code` text, reaches byte
// 11 of the frames on the wire (the oracle reads them off the encoded bytes).
TEST(FaultSimulation, EveryDipSwitchCodeReachesTheWire) {
  for (int code = 0; code <= 0xFF; ++code) {
    const auto p =
        play("0 connect\n20 button leftshoulder 1\n60 axis lefty -32768\n200 end\n", static_cast<std::uint8_t>(code));
    EXPECT_EQ(p.violation, "") << "code " << code;
    EXPECT_FALSE(p.enabled.empty()) << "code " << code;
  }
}

// The weak spots (issue 35, item 3): what only a few seeds reached, each as a
// script with the frames it must give.

// A layer toggled (the arm: the right stick's click) while not enabled is no
// layer on enabling: a click without the deadman toggles nothing. The left
// stick, pushed after the enabling press, drives; no arm signal moves.
TEST(FaultSimulation, ALayerToggledWhileNotEnabledIsNoLayerOnEnabling) {
  const auto p = play(
      "0 connect\n40 button rightstick 1\n60 button rightstick 0\n200 button leftshoulder 1\n"
      "300 axis lefty -32768\n400 end\n");
  EXPECT_EQ(p.violation, "");
  ASSERT_TRUE(p.frames.contains(360));
  EXPECT_EQ(p.frames.at(360)[protocol::signal_id("drive")], 255);
  for (const auto& [t, s] : p.frames) {
    EXPECT_EQ(s[protocol::signal_id("shoulder_ccw")] + s[protocol::signal_id("shoulder_cw")], 0) << t;
  }
}

// The deadman tapped during a reset hold: the hold is no reset, the stop stays,
// and nothing the deadman does after it drives.
TEST(FaultSimulation, ADeadmanTapDuringAResetHoldIsNoReset) {
  const auto p = play(
      "0 connect\n20 button leftshoulder 1\n60 axis lefty -32768\n100 button guide 1\n110 button guide 0\n"
      "120 button leftshoulder 0\n200 button back 1\n200 button start 1\n1201 button leftshoulder 1\n"
      "1211 button leftshoulder 0\n2600 button back 0\n2600 button start 0\n2700 button leftshoulder 1\n"
      "3000 end\n");
  expect_driving_only_before(p, 120);
}

// A trigger deadman held as the pad reconnects is no press: neutral until it
// is let go and squeezed again.
TEST(FaultSimulation, ATriggerHeldAtReconnectIsNoPress) {
  const auto p = play(
      "0 connect Pad A\n20 axis lefttrigger 20000\n200 disconnect\n300 connect Pad A\n"
      "300 axis lefttrigger 20000\n600 axis lefttrigger 0\n700 axis lefttrigger 20000\n900 end\n",
      kCode, ANDROS_TEST_DATA_DIR "/simulation/mappings/trigger.yaml");
  EXPECT_EQ(p.violation, "");
  ASSERT_FALSE(p.enabled.empty());
  EXPECT_LT(p.enabled.front(), 200);
  EXPECT_EQ(first_enabled_from(p, 200), 720);
}

// Another pad within one frame (lost at 105, Pad B at 110 with the deadman
// held as it appears) is a new session: neutral from the frame at 120 until
// a fresh press on it.
TEST(FaultSimulation, APadWithinOneFrameIsANewSession) {
  const auto p = play(
      "0 connect Pad A\n20 button leftshoulder 1\n60 axis lefty -32768\n105 disconnect\n110 connect Pad B\n"
      "110 button leftshoulder 1\n110 axis lefty -32768\n300 button leftshoulder 0\n340 button leftshoulder 1\n"
      "400 axis lefty 0\n440 axis lefty -32768\n600 end\n");
  EXPECT_EQ(p.violation, "");
  EXPECT_EQ(first_enabled_from(p, 120), 360);
}

// The stop tapped during a reload's neutral frames latches for when the
// reload is done: stopped after it, whatever the deadman does.
TEST(FaultSimulation, AStopDuringAReloadLatches) {
  const auto p = play(
      "0 connect\n20 button leftshoulder 1\n60 axis lefty -32768\n100 reload\n130 button guide 1\n"
      "140 button guide 0\n300 button leftshoulder 0\n340 button leftshoulder 1\n600 end\n");
  expect_driving_only_before(p, 120);
}

// The operator's pad back while stopped, the supervisor's reset chord made
// at the same instant and the deadman tapped on the new pad within that
// frame: the deadman was touched during the hold, so it is no reset
// (docs/safety-states.md: every stop button and the deadman released
// throughout); the new session's presses count from its connect. Stopped to
// the end, whatever the deadman does after.
TEST(FaultSimulation, ADeadmanTapOnAPadBackWithinTheResetsFirstFrameIsNoReset) {
  const auto p = play(
      "0 connect Pad A\n0 supervisor connect Sup A\n20 button leftshoulder 1\n60 axis lefty -32768\n"
      "100 button guide 1\n110 button guide 0\n200 disconnect\n1085 connect Pad A\n"
      "1085 supervisor button back 1\n1085 supervisor button start 1\n1091 button leftshoulder 1\n"
      "1101 button leftshoulder 0\n3201 supervisor button back 0\n3201 supervisor button start 0\n"
      "3258 button leftshoulder 1\n3500 end\n");
  expect_driving_only_before(p, 100);
}

// The supervisor's consent is fresh and held, never latched (docs/mapping.md):
// held since before the weapons layer is entered it counts only once released
// and pressed again, and a fire button held when it comes waits until pressed
// again. Weapon 1 (the weapons layer RB, LT armed, A) fires only from the
// fresh press after each.
TEST(FaultSimulation, TheSupervisorsConsentIsFreshNeverLatched) {
  const auto p = play(
      "0 connect Pad A\n0 supervisor connect Sup A\n20 button leftshoulder 1\n100 supervisor button a 1\n"
      "200 button rightshoulder 1\n240 axis lefttrigger 32767\n300 button a 1\n400 button a 0\n"
      "500 supervisor button a 0\n540 supervisor button a 1\n600 button a 1\n700 button a 0\n"
      "800 supervisor button a 0\n900 button a 1\n1000 supervisor button a 1\n1200 button a 0\n"
      "1240 button a 1\n1300 end\n",
      kCode, ANDROS_TEST_DATA_DIR "/simulation/mappings/consent.yaml", true);
  EXPECT_EQ(p.violation, "");
  std::vector<std::int64_t> fired;
  for (const auto& [t, s] : p.frames) {
    if (s[protocol::signal_id("weapon_1")] != 0) fired.push_back(t);
  }
  EXPECT_EQ(fired, (std::vector<std::int64_t>{600, 640, 680, 1240, 1280, 1320}));
}

// Speed levels (docs/mapping.md, `scale`; the simulated consent.yaml: misc1
// up, paddle1 down, 25%, 50%, 100% from the slowest, the trim 124): full
// forward drives 157, 190 or 255; a change of level holds the stick back at
// the trim until seen at rest; down at the slowest stays there (no change, it
// drives on); two presses within one frame count each; presses while not
// enabled do nothing, and a pad back starts at the slowest.
TEST(FaultSimulation, SpeedLevelsWaitForTheStickAtRestAndStopAtTheSlowest) {
  const auto p = play(
      "0 connect Pad A\n20 button leftshoulder 1\n60 axis lefty -32768\n200 button misc1 1\n210 button misc1 0\n"
      "300 axis lefty 0\n400 axis lefty -32768\n500 button paddle1 1\n510 button paddle1 0\n600 axis lefty 0\n"
      "700 axis lefty -32768\n800 button paddle1 1\n810 button paddle1 0\n900 button misc1 1\n905 button misc1 0\n"
      "910 button misc1 1\n915 button misc1 0\n1000 axis lefty 0\n1100 axis lefty -32768\n1200 disconnect\n"
      "1300 connect Pad A\n1320 button misc1 1\n1330 button misc1 0\n1340 button leftshoulder 1\n"
      "1400 axis lefty -32768\n1500 end\n",
      kCode, ANDROS_TEST_DATA_DIR "/simulation/mappings/consent.yaml");
  EXPECT_EQ(p.violation, "");
  const std::map<std::int64_t, int> drive = {{80, 157},  {240, 124}, {320, 124}, {440, 190},  {520, 124},
                                             {720, 157}, {840, 157}, {920, 124}, {1120, 255}, {1440, 157}};
  for (const auto& [t, want] : drive) {
    ASSERT_TRUE(p.frames.contains(t)) << t;
    EXPECT_EQ(p.frames.at(t)[protocol::signal_id("drive")], want) << "at " << t;
  }
}

// The engine at fault from t=200 on, each fault of faulty_frames.hpp in
// turn, while driving (to 400) and while not (from 440): the frame gate
// refuses its frames, so that every frame on the wire keeps the oracle's
// rules up to the gate's first trip, and it trips.
TEST(FaultSimulation, TheFrameGateRefusesAnEngineAtFault) {
  Library library;
  const auto script = input::parse_event_script(
      "0 connect\n20 button leftshoulder 1\n60 axis lefty -32768\n400 button leftshoulder 0\n"
      "600 button leftshoulder 1\n800 end\n",
      "gate.events");
  for (const auto& kind : test::kFaultKinds) {
    const auto out = test::simulate(
        library, kSimulationHd1, script, kind.weapons, kCode, [](const TickReport&) {},
        test::InjectedFault{kind.fault, 200});
    EXPECT_EQ(out.violation, "") << kind.name;
    EXPECT_EQ(out.coverage.gate_refused, 1) << kind.name;
  }
}

// Scripts the simulation found (tests/data/simulation/): each broke a rule
// once, and each header says what the frames must be.
TEST(FaultSimulation, FoundScripts) {
  Library library;
  const std::string mapping_file = mapping::find_robot_mapping("HD1", {ANDROS_MAPPINGS_DIR}).string();
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(ANDROS_TEST_DATA_DIR "/simulation")) {
    if (entry.path().extension() == ".events") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  ASSERT_FALSE(files.empty());
  for (const auto& file : files) {
    std::ifstream in(file);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto script = input::parse_event_script(text, file.string());
    for (const bool weapons : {false, true}) {
      const auto out = test::simulate(library, mapping_file, script, weapons, kCode);
      EXPECT_EQ(out.violation, "") << file.filename().string() << (weapons ? " with --weapons" : "");
    }
  }
}

}  // namespace
}  // namespace andros::run
