#pragma once
/// The flight recorder's session file (docs/recording.md): one text line per
/// record, `SEQ KIND FIELDS... HASH`, where HASH is the SHA-256 of the
/// previous record's HASH (32 bytes; zeros before the first) and of this
/// line up to the space before HASH. A record altered, removed or moved
/// breaks the chain at that record. read_checked_session() is the one
/// reading every command makes: it checks the chain and turns the records
/// back into what replay and plot need in the same pass, so that no two
/// commands tell a session apart.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "andros/base/error.hpp"
#include "andros/base/sha256.hpp"
#include "andros/input/input_state.hpp"
#include "andros/input/pad_identity.hpp"
#include "andros/link/link_status.hpp"
#include "andros/mapping/model.hpp"
#include "andros/protocol/frame.hpp"
#include "andros/run/bridge.hpp"
#include "andros/run/operating_state.hpp"

namespace andros::record {

/// The first record's kind: a file whose first line is `0 andros-session ...` is a session.
inline constexpr std::string_view kSessionMagic = "andros-session";
/// The format written. 3: every text that came from outside (the settings'
/// paths and mapping texts, the host, a reload's message, a gate's fault, a
/// layer's name, a link's detail, the end's why) is written as
/// printable_text() writes it, inside its JSON string, so that any bytes are
/// recorded whole and the record is always valid UTF-8 (format 2 wrote them
/// as JSON strings of the text itself, and could not hold bytes that are not
/// UTF-8); and the loop's frame record is written again (the same frame,
/// gap=0) when kFrameRecordPeriodMs have passed since the last, so that no
/// tick is more than that after a record (a reader refuses a session of
/// format 3 or later whose ticks stretch further: check_record_spacing()).
/// 2: the settings' rate is `rate_millihertz`; format 1 named it `rate_mhz`
/// (read as megahertz by everyone). 4: a `transition` record for each step
/// of the machine that changed its state (its event and who it came from),
/// and a stop record for each stop press of a tick (format 3 wrote the
/// tick's last). All four are read.
inline constexpr int kSessionFormat = 4;
/// The first format with transition records.
inline constexpr int kTransitionFormat = 4;
/// The first format whose texts are written as printable_text() writes them.
inline constexpr int kEscapedTextFormat = 3;
/// The first format whose frame records are kFrameRecordPeriodMs apart at most.
inline constexpr int kSpacedFormat = 3;
/// The longest a frame record holds in a session of kSpacedFormat: the ticks
/// it stands for lie within this of its own. Reading such a session (replay's
/// ticks, export's rows) is then work linear in its records: at most
/// records x 60 s x rate ticks.
inline constexpr std::int64_t kFrameRecordPeriodMs = 60'000;
inline constexpr int kOldestSessionFormat = 1;
inline constexpr std::string_view kSessionExtension = ".andros-session";
/// The longest line read (checked while reading: a longer one is refused
/// before more of it is held). The longest record is the settings': the
/// mapping chain's text, JSON-escaped; the recorder drops a longer one.
inline constexpr std::size_t kMaxSessionLine = std::size_t{4} * 1024 * 1024;
/// The longest session read: its times and ticks lie within 24 h (an event
/// script's bound), so that replay and plot do bounded work.
inline constexpr std::int64_t kMaxSessionMs = std::int64_t{24} * 3600 * 1000;

/// True when text (a file's first line, or more) starts a session.
bool is_session_start(std::string_view first_line);

/// Refuses at once, never opening or waiting on it, a path that is there and
/// is not a regular file: InputError `FILE: error: is a FIFO, not a session
/// file` (a directory, a character device, a socket...).
void require_session_file(const std::filesystem::path& path);

/// Turns payloads into chained lines: `SEQ PAYLOAD HASH\n`.
class RecordChain {
 public:
  /// The next record's whole line, newline included.
  std::string line(std::string_view payload);
  [[nodiscard]] std::uint64_t records() const { return seq_; }
  /// Back to an earlier place (records, and the last one's hash): the lines
  /// made since were not written, and the chain goes on from the last that was.
  void rewind(std::uint64_t records, const Sha256Digest& last) {
    seq_ = records;
    last_ = last;
  }
  [[nodiscard]] const Sha256Digest& last() const { return last_; }

 private:
  Sha256 sha_;
  Sha256Digest last_{};
  std::uint64_t seq_ = 0;
};

/// A file of a mapping's `extends` chain, as it was read.
struct MappingSource {
  std::string path;  ///< canonical, as the loader read it
  std::string text;
};

/// Reads each file of a mapping's chain (Mapping::chain). Throws InputError
/// for a file that cannot be read.
std::vector<MappingSource> read_mapping_sources(const std::vector<std::string>& chain);

/// What the engine was made from: the settings that change frames, and the mapping.
struct SessionSettings {
  std::string robot;
  std::string mapping_file;
  std::int64_t rate_millihertz = 0;
  bool weapons = false;
  std::uint8_t code = 0;
  int center = mapping::kDefaultCenter;
  std::string port;
  int baud = 0;
  std::string input;
  std::string config;
  /// A supervisor's controller is configured (`--supervisor`, a script that
  /// addresses one): driving needs it too, in the replay as in the run.
  bool supervised = false;
  std::vector<MappingSource> sources;  ///< the mapping's file first, then each it extends
};

struct FrameRecord;

/// A trainer run's course (`course {...}`, after the settings): its name,
/// the file it was read from (a label) and its text, kept as a mapping's is.
struct CourseRecord {
  std::string name;
  std::string path;
  std::string text;
  int line = 0;  ///< the record's line in the file
};

/// A trainer run's score (`score T {...}`, before the end): the JSON object
/// the trainer made of its frames and its course (docs/trainer.md, "The score").
struct ScoreRecord {
  std::int64_t t_ms = 0;
  std::string json;
  int line = 0;
};

/// The payloads of the records, one a function (no SEQ, no hash).
namespace payload {
std::string header();
std::string program(std::string_view version);
std::string started(std::string_view local_time, long pid, std::string_view host);
/// `settings {json}`: the settings and the mapping's files (text and SHA-256).
std::string settings(const SessionSettings& settings);
std::string event(const input::InputEvent& event);
std::string request(std::int64_t t_ms, run::Request request);
std::string pause(std::int64_t t_ms);
std::string reload(std::int64_t t_ms, const run::ReloadOutcome& outcome);
/// `frame TICK T RESULT DATA gap=N`: written when the frame, its result or
/// the tick's place changes; the ticks between repeat the last one.
std::string frame(const run::TickReport& report, std::int64_t gap);
/// The same line from a frame record as read (replay's comparison makes the recorded one again).
std::string frame(const FrameRecord& record);
std::string state(std::int64_t t_ms, run::OpState state);
/// `transition T FROM EVENT TO WHO` (format 4): a transition of the machine
/// that changed its state, in the session's own words (state_word()...).
std::string transition(std::int64_t t_ms, const run::Transition& transition);
/// `gate T "FAULT"`: the frame gate replaced the frame of tick T (an internal error).
std::string gate(std::int64_t t_ms, std::string_view fault);
/// `stop T WHO "NAME"` / `reset T WHO`: who stopped, who reset.
/// PAD as JSON: name, path, serial, guid, each as printable_text() writes
/// it (text from a controller's descriptors may be any bytes).
/// again: pressed while stopped, the latch and whose it is unchanged (`"again":true` in PAD).
std::string stop(std::int64_t t_ms, run::StopBy by, const input::PadIdentity& pad, bool again = false);
std::string reset(std::int64_t t_ms, run::StopBy by, const input::PadIdentity& pad);
std::string layer(std::int64_t t_ms, std::string_view layer);
/// t_ms -1: the link before the first tick.
std::string link(std::int64_t t_ms, const link::LinkStatus& status);
std::string input_end(std::int64_t t_ms);
/// `course {"name":..,"path":..,"sha256":..,"text":..}`: a trainer run's course, its text escaped as a mapping's.
std::string course(const CourseRecord& course);
/// `score T {...}`: a trainer run's score (one line of JSON).
std::string score(std::int64_t t_ms, std::string_view json);
/// `dropped N "WHY"`: N records went missing here, and why the last of them
/// did ("No space left on device", "File too large", "the queue was full...").
std::string dropped(std::uint64_t count, std::string_view why);
std::string end(std::int64_t t_ms, std::int64_t last_tick, std::uint64_t frames_sent, std::string_view why);
}  // namespace payload

/// The chain's verdict (read_checked_session).
struct VerifyResult {
  bool intact = false;
  std::uint64_t records = 0;  ///< records read in order (all of them when intact)
  bool closed = false;        ///< the session has its end record, its last whole one
  std::string last_hash;      ///< the last record's hash (compare with the log's closing line)
  std::string problem;        ///< the first record altered, removed or reordered
  /// Not 0: the file's last line, half a record, was cut short there (a run
  /// cut off: power lost, a full disk); the records before it are intact.
  /// A line without its newline is such a line, even when it would chain:
  /// it is never read as a record.
  int cut_short_line = 0;
  /// NUL bytes after the last whole record, to the end of the file: the
  /// blocks a power loss left unwritten (after an end record too).
  std::uint64_t nul_tail = 0;
};

/// The chain's verdict of the session at path: read_checked_session(path).verdict.
VerifyResult verify_session(const std::filesystem::path& path);

/// "cut short at line N: the run was cut off, power lost or disk full; the R records before it are intact".
std::string cut_short_text(const VerifyResult& result);

/// Where an input is in effect: `t_ms` from a record.
struct TimedText {
  std::int64_t t_ms = 0;
  std::string text;
  int line = 0;  ///< the record's line in the file (replay names a difference by it)
};

struct FrameRecord {
  std::int64_t tick = 0;
  std::int64_t t_ms = 0;
  bool offered = true;  ///< false: nothing was offered (suspended by a script)
  link::SendResult result = link::SendResult::kSent;
  protocol::DataBytes data{};
  std::int64_t gap = 0;  ///< ticks the live loop did not run just before this one (a stall, a pause)
  int line = 0;          ///< the record's line in the file

  /// The frame reached the vehicle: offered and taken by the link.
  [[nodiscard]] bool delivered() const { return offered && result == link::SendResult::kSent; }
};

/// What became of a frame record's frame, as the record says it: sent, busy, down, or none (nothing offered).
std::string_view result_name(const FrameRecord& frame);

struct ReloadRecord {
  std::int64_t t_ms = 0;
  run::ReloadOutcome outcome;
  std::optional<SessionSettings> settings;  ///< what an ok reload put in place
};

struct LinkRecord {
  std::int64_t t_ms = 0;  ///< -1: before the first tick
  link::LinkState state = link::LinkState::kConnecting;
  bool far_end_reading = true;
  std::string detail;
};

struct StateRecord {
  std::int64_t t_ms = 0;
  run::OpState state = run::OpState::kNoLink;
  int line = 0;  ///< the record's line in the file
};
/// `transition T FROM EVENT TO WHO` (format 4 on): the machine's step at tick T.
struct TransitionRecord {
  std::int64_t t_ms = 0;
  run::Transition transition{};  ///< from, event, to, who (its pad: the stop and reset records')
  int line = 0;                  ///< the record's line in the file
};

/// `stop T operator|supervisor|gate "NAME" {PAD}` (whose stop latched, or
/// became whose, or was pressed again while latched (`"again":true`); the gate's: the frame
/// gate tripped), `reset T operator|supervisor "NAME" {PAD}` (who reset it),
/// PAD the physical pad's identity as JSON (path, serial, guid). Sessions
/// of earlier versions have no PAD, and a reset no NAME.
struct StopRecord {
  std::int64_t t_ms = 0;
  bool reset = false;  ///< a reset; false: a stop
  run::StopBy by = run::StopBy::kOperator;
  std::string name;          ///< the controller's name
  input::PadIdentity pad{};  ///< the physical pad that pressed it (empty: not recorded, or the gate's)
  /// A stop pressed again while stopped: recorded, but the latch and whose it is are unchanged.
  bool again = false;
  bool has_pad = true;  ///< false: an earlier version's record, without PAD (its name alone, or nothing)
  int line = 0;         ///< the record's line in the file
};

struct EndRecord {
  std::int64_t t_ms = 0;
  std::int64_t last_tick = 0;
  std::uint64_t frames_sent = 0;
  std::string why;
  int line = 0;  ///< the record's line in the file
};

/// A session's records, by kind, in time order.
struct Session {
  std::string path;
  std::string version;  ///< of the program that recorded it
  std::string started;  ///< local time, ISO 8601
  long pid = 0;
  std::string host;
  SessionSettings settings;
  std::vector<input::InputEvent> events;
  std::vector<TimedText> requests;   ///< "stop", "suspend", "resumed", "reload"
  std::vector<std::int64_t> pauses;  ///< the time the loop went on after each job-control stop
  std::vector<ReloadRecord> reloads;
  std::vector<FrameRecord> frames;
  std::vector<StateRecord> states;
  std::vector<TransitionRecord> transitions;  ///< none before format 4
  std::vector<TimedText> gate_trips;          ///< frames the frame gate replaced: when, and the rule they broke
  std::vector<StopRecord> stops;              ///< stops and resets, in order
  std::vector<TimedText> layers;
  std::vector<LinkRecord> links;
  std::optional<std::int64_t> input_end;
  std::uint64_t dropped = 0;
  /// Why the last `dropped` record's records went missing, as its WHY says
  /// (a write's error: "No space left on device", "File too large", "Disk
  /// quota exceeded"; or the full queue); "" when it gave none.
  std::string dropped_why;
  /// Its records say the recording stopped for want of room: a `dropped`
  /// record's WHY is a full disk's, a file-size limit's or a quota's, or
  /// (not closed) they end with a `dropped` record that gives no WHY (an
  /// earlier writer's). The last frame record's tick before it (-1: none).
  std::optional<std::int64_t> stopped_for_room;
  std::optional<EndRecord> end;
  std::optional<CourseRecord> course;  ///< a trainer run's course
  std::optional<ScoreRecord> score;    ///< and its score
  int format = 0;                      ///< its header's: how its texts and frame records are written
  int cut_short_line = 0;              ///< not 0: its last line, half a record, was left out (VerifyResult's)

  /// The frame record in effect at tick (the last one at or before it), or null.
  [[nodiscard]] const FrameRecord* frame_at(std::int64_t tick) const;
  /// Ticks the live loop ran (a gap's ticks are not counted).
  [[nodiscard]] std::int64_t live_ticks() const;
  /// The length in ms: the last tick's time.
  [[nodiscard]] std::int64_t length_ms() const;
  /// Frames the link took: the end record's count, or, without one, those
  /// the frame records read show (to the last of them).
  [[nodiscard]] std::uint64_t frames_sent() const;
};

/// A session read once: the chain's verdict, and what the records of its
/// intact part say.
struct CheckedSession {
  VerifyResult verdict;
  /// The records before the chain's first break (all of them when intact),
  /// never a last line cut short or a NUL tail; nullopt when unreadable.
  std::optional<Session> session;
  /// Why the records are not a session's: the first record (before the
  /// chain breaks) that does not read, at FILE:LINE, or a session without
  /// its settings.
  std::optional<InputError> unreadable;
};

/// The one reading of the session at path, for verify, sessions, replay,
/// plot and export: the chain checked and the records read in the same
/// pass, each record checked against what a session holds (a tick at its
/// time at the recorded rate, within kMaxSessionMs; the end's tick at or
/// after the last frame record's, its frames at most its ticks). After a
/// record that does not read, the chain is still checked. Throws InputError
/// for a path that is not a regular file (require_session_file), RuntimeError
/// for a read that fails.
///
/// What of the records is kept: all of them, or (verify's) only what the
/// verdict needs, each record checked all the same, in memory of a line's
/// size: the settings, the end, the dropped count and the last frame record.
enum class Keep : std::uint8_t { kRecords, kVerdict };
CheckedSession read_checked_session(const std::filesystem::path& path, Keep keep = Keep::kRecords);

/// read_checked_session()'s records: throws its `unreadable` error. A
/// session that is not intact gives the records before the break.
Session read_session(const std::filesystem::path& path);

/// A session of kSpacedFormat or later without dropped records: each frame
/// record's ticks (to the next record's, less a gap's, or to the end's)
/// within kFrameRecordPeriodMs of it. Throws InputError at the record (the
/// end's, for the ticks after the last frame record) that breaks it: a
/// session crafted to make replay and export step far more ticks than it
/// has records is refused before they start. any_format: a session of an
/// earlier format held to it too (`sessions` replays only such a one).
/// frames_checked: the frame records were checked as they were read (spacing_error(), one
/// pair at a time: a reader that does not keep them all), only the end's ticks are left.
void check_record_spacing(const Session& session, bool any_format = false, bool frames_checked = false);
/// The error for the ticks a frame record stands for, from it through tick
/// `through` (`line`: the record where they end), when they run
/// kFrameRecordPeriodMs or more past it; nullopt when they do not.
std::optional<InputError> spacing_error(const Session& session, const FrameRecord& from, std::int64_t through,
                                        int line);

/// How the session ends, as verify says it: `closed: ...` (and a NUL tail
/// after it), or `not closed: ...`: recording stopped for want of room
/// (room_text), or the run still going, crashed, or its last records removed.
std::string closing_text(const CheckedSession& checked);

/// "recording stopped at tick T: the disk was full or a file-size limit was reached" (Session::stopped_for_room).
std::string room_text(const Session& session);

std::string_view request_name(run::Request request);
std::optional<run::Request> parse_request(std::string_view name);
/// The session's own words for the machine (docs/recording.md), kept apart
/// from what the screen says, so that a change of the display's text never
/// changes a session: a state record's STATE ("not enabled", "stopping"...),
/// and a transition record's FROM and TO (the same, a space as `-`:
/// "not-enabled"), EVENT ("deadman-fresh-press") and WHO ("operator", "script").
std::string_view state_word(run::OpState state);
std::optional<run::OpState> parse_op_state(std::string_view name);
std::string_view event_word(run::OpEvent event);
std::string_view who_word(run::Who who);
/// A transition record's FIELDS: "not-enabled deadman-fresh-press enabled operator"; nullopt when not such.
std::optional<run::Transition> parse_transition(std::string_view fields);
/// A stop record's WHO: "operator", "supervisor", "gate" (the frame gate's trip).
std::string_view stopper_word(run::StopBy by);
std::optional<run::StopBy> parse_stopper(std::string_view word);

}  // namespace andros::record
