#pragma once
/// The simulated vehicle: what a real Andros would do with the frames it
/// receives. Fed only decoded frames, at the times they arrive, it integrates
/// them deterministically (the same frames at the same times give the same
/// state, bit for bit): the tracks, the flippers, the arm, the cameras, the
/// weapons and the laser, and its own watchdog. A frame with a bad checksum
/// or a broken validation rule is ignored, as the vehicle would.
///
/// Axes as ROS's REP 103: x and y on the ground in metres, heading in degrees
/// counter-clockwise from +x; the vehicle starts at (0, 0, 0), facing +x.

#include <array>
#include <cstdint>
#include <deque>
#include <optional>

#include "andros/protocol/decoder.hpp"
#include "andros/vehicle/course.hpp"
#include "andros/vehicle/robot_figures.hpp"

namespace andros::vehicle {

struct Pose {
  double x = 0;        ///< metres
  double y = 0;        ///< metres
  double heading = 0;  ///< degrees, counter-clockwise from +x, in (-180, 180]
};

struct ArmPose {
  double torso = 0;            ///< degrees
  double shoulder = 0;         ///< degrees up from lying forward along the body (0 stowed)
  double elbow = 0;            ///< degrees the forearm opens from folded back along the upper arm (0 stowed)
  double wrist = 0;            ///< pitch, degrees
  double wrist_extension = 0;  ///< metres
  double gripper_rotation = 0;
  double gripper_opening = 0;  ///< 0 closed .. 1 open
};

/// The cameras by number, as the video bits select them (an assumption: the
/// ICD gives the bits, not what is wired to each input).
enum class Camera : std::uint8_t { kNone = 0, kFrontDrive = 1, kGripper = 2, kPtz = 3, kRearDrive = 4 };

struct Cameras {
  Camera main = Camera::kFrontDrive;  ///< main_video_2/3/4, none of them: camera 1
  Camera inset = Camera::kNone;       ///< inset_video_1/2, inset_3/4; none: no inset
  double pan = 0;                     ///< degrees, continuous
  double tilt = 0;                    ///< degrees
  double zoom = 1;                    ///< 1x ..
  double focus = 0.5;                 ///< 0 .. 1
  double iris = 0.5;                  ///< 0 .. 1
  double extender = 0;                ///< metres the PTZ camera's mast is raised
};

/// What the vehicle met on a course (all zero on open ground).
struct CourseState {
  double elevation = 0;  ///< metres: the ground's height under the vehicle's centre
  double pitch = 0;      ///< degrees, nose up positive: the slope under it along its heading
  /// Times the body or the arm came against a wall, a box, the door or the ground's edge.
  std::uint32_t contacts = 0;
  bool body_touching = false;  ///< pushing against something now
  bool arm_touching = false;
  /// Times it stopped at a slope steeper than it climbs, or at stairs with its flippers down.
  std::uint32_t climbs_refused = 0;
  bool climb_blocked = false;
  std::size_t gates = 0;  ///< gates passed, in order
  double door_angle = 0;  ///< degrees open (0 closed)
  bool door_held = false;
  double door_grip_bearing = 0;  ///< held: the gripper's bearing from the hinge, less the door's angle
  Point package;                 ///< the package's centre on the ground
  double package_z = 0;
  bool package_held = false;
  bool package_lifted = false;     ///< it has been lifted
  bool package_delivered = false;  ///< set down inside its drop area
  /// Metres the centre of mass is from the edge it would tip over (the tracks' or the flippers' ends).
  double tip_margin = 0;
  bool tip_warning = false;  ///< within the figures' tip_warning_m of tipping
  std::uint32_t tip_warnings = 0;
  bool tipped = false;  ///< tipped over (or fell off an edge): nothing moves any more; the run failed
  bool laser_on_target = false;
  std::uint32_t hits = 0;              ///< weapons fired with the laser on the target
  std::uint32_t fired_off_target = 0;  ///< weapons fired without it
  bool in_finish = false;              ///< inside the finish area, facing as it asks
};

/// The fire outputs, in this order: weapon_1..6, then shotgun.
inline constexpr std::size_t kWeaponCount = 7;

struct VehicleState {
  std::int64_t time_ns = 0;   ///< the time the state is integrated to
  std::int64_t start_ns = 0;  ///< the first frame's arrival
  Pose pose;
  double speed = 0;      ///< metres per second along the heading, now: the last valid frame's (no inertia)
  double turn_rate = 0;  ///< degrees per second, counter-clockwise, now: the last valid frame's
  double front_flipper = 0;
  double rear_flipper = 0;
  ArmPose arm;
  Cameras cameras;
  double light = 0;  ///< 0 .. 1, from its analog byte
  bool laser = false;
  bool tool_on = false;
  bool enable_key = false;
  /// Times each output fired (on the rise of its bit in a frame that allowed it).
  std::array<std::uint32_t, kWeaponCount> fired{};
  /// Each output's bit in the last frame taken (what a rise is measured from).
  std::array<bool, kWeaponCount> fire_bits{};
  bool safety = false;        ///< the last frame's safety bit (arm and articulation may move)
  bool drive = false;         ///< its safety and drive-brake bits both say drive
  bool watchdog = false;      ///< no valid frame for the watchdog's time: stopped
  bool started = false;       ///< a frame has arrived
  std::uint64_t frames = 0;   ///< frames taken
  std::uint64_t ignored = 0;  ///< frames ignored (bad checksum, a validation rule broken)
  CourseState course;
};

/// Where the weapon outputs' names come from: their canonical signal names.
std::string_view weapon_name(std::size_t index);

class VehicleModel {
 public:
  /// On open ground (from 0, 0, 0), or on course: from its start, met by what stands on it.
  explicit VehicleModel(const RobotFigures& figures, std::optional<Course> course = std::nullopt);

  /// A frame that arrived at now_ns (monotonic): the state integrated to
  /// then, and the frame taken when valid (ignored when not).
  void on_frame(const protocol::DecodedFrame& frame, std::int64_t now_ns);
  /// Integrates to now_ns with the commands in force (for a view between
  /// frames, and the watchdog). Earlier times than the state's are ignored.
  void advance(std::int64_t now_ns);

  [[nodiscard]] const VehicleState& state() const { return state_; }
  [[nodiscard]] const RobotFigures& figures() const { return figures_; }
  [[nodiscard]] const std::optional<Course>& course() const { return course_; }
  /// The course is done: every gate passed in order, the package delivered,
  /// the finish reached, the target hit (what it has of these), not tipped over.
  [[nodiscard]] bool course_done() const;
  /// The ground track: a point every kTrailStep metres moved, the newest last,
  /// at most kTrailPoints (the oldest dropped).
  [[nodiscard]] const std::deque<Pose>& trail() const { return trail_; }

  static constexpr double kTrailStep = 0.05;
  static constexpr std::size_t kTrailPoints = 20000;
  /// On a course, motion is integrated in steps of at most this (seconds), each checked against it.
  static constexpr double kCourseStep = 0.01;

  /// What the last valid frame commands, as rates (-1..1 for a joint).
  struct Command {
    double left = 0;  ///< track, -1 .. 1 of the speed level's top speed
    double right = 0;
    double speed_scale = 0;
    int front_flipper = 0;
    int rear_flipper = 0;
    int torso = 0, shoulder = 0, elbow = 0, wrist = 0, wrist_extension = 0, gripper_rotation = 0, gripper = 0;
    double arm_rate = 0;  ///< arm_speed / 255
    int pan = 0, tilt = 0, zoom = 0, focus = 0, iris = 0, extender = 0;
  };

 private:
  /// Integrates [state_.time_ns, until_ns] under command_ (none past the watchdog).
  void integrate(std::int64_t until_ns);
  void move(double seconds);
  /// state_'s speed and turn rate from command_.
  void commanded_rates();
  /// The pose the tracks reach from p in seconds under command_; v and w their speed and turn rate.
  [[nodiscard]] Pose drive(const Pose& p, double seconds, double& v, double& w) const;
  void move_joints(double seconds);
  // The course's part (vehicle_course.cpp).
  void step_on_course(double seconds);
  void course_pose(const Pose& next);
  void course_arm(const ArmPose& before);
  void course_grip(double opening_before);
  void course_balance();
  void course_fired();
  void course_laser();
  void take(const protocol::DataBytes& data);
  void add_trail_point();

  RobotFigures figures_;
  std::optional<Course> course_;
  VehicleState state_;
  Command command_;
  std::int64_t last_valid_ns_ = 0;
  std::deque<Pose> trail_;
};

}  // namespace andros::vehicle
