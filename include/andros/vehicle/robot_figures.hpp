#pragma once
/// The simulated vehicle's figures per robot type: size, weight, speed, turn,
/// joint limits and rates. Each figure carries where it comes from; most are
/// assumptions (no public figure was found for them), said so here and in
/// docs/trainer.md. The trainer draws and moves the vehicle with these.

#include <string_view>

namespace andros::vehicle {

/// Where a figure comes from.
enum class Source : unsigned char {
  kPublished,  ///< a published figure (the HD-1's, as issue 37 and the Andros brochure give it)
  kAssumed,    ///< no public figure: chosen to look and behave plausibly, to be confirmed
};

struct Figure {
  double value = 0;
  Source source = Source::kAssumed;
};

/// A joint's range and its rate at full command (for the arm: at arm_speed 255).
struct JointFigure {
  Figure min;  ///< degrees (metres for an extension, 0..1 for the gripper's opening)
  Figure max;
  Figure rate;  ///< units per second
};

struct RobotFigures {
  std::string_view robot;  ///< the type's canonical name (protocol::kRobotTypes)
  // The body, stowed.
  Figure length_m;
  Figure width_m;
  Figure height_m;
  Figure mass_kg;
  Figure top_speed_kmh;       ///< at speed high, drive at full
  Figure turn_rate_dps;       ///< a neutral turn at full pivot, speed high
  Figure low_speed_scale;     ///< speed_low's share of the top speed
  Figure medium_speed_scale;  ///< neither speed bit: its share
  bool neutral_turn = true;
  bool stair_climbing = true;
  // The articulation (flippers): 0 is along the ground, up is positive.
  JointFigure front_flipper;
  JointFigure rear_flipper;
  Figure flipper_m;  ///< a flipper's length
  // The arm: angles in degrees, 0 stowed along the body; lengths in metres.
  JointFigure torso;
  JointFigure shoulder;
  JointFigure elbow;
  JointFigure wrist;            ///< the wrist's pitch (wrist_cw / wrist_ccw)
  JointFigure wrist_extension;  ///< metres (wrist_extend_right out, wrist_extend_left in)
  JointFigure gripper_rotation;
  JointFigure gripper_opening;  ///< 0 closed .. 1 open
  Figure upper_arm_m;
  Figure forearm_m;
  // The PTZ camera: pan, tilt, zoom (1x..), focus and iris (0..1), the extender (metres).
  JointFigure pan;
  JointFigure tilt;
  JointFigure zoom;
  JointFigure focus;
  JointFigure iris;
  JointFigure extender;
  /// With no valid frame for this long the vehicle stops everything it was
  /// told to do (its own watchdog).
  Figure watchdog_ms;
  /// Drive and pivot within this many counts of 128 are still (the ICD's
  /// example carries 0x7F and 0x7E at rest: ADC noise around the centre).
  Figure deadband_counts;
  // On a course (course.hpp): what the trainee must learn the vehicle cannot do.
  Figure gripper_m;           ///< the gripper's length past the wrist (its extension adds to it)
  Figure max_climb_deg;       ///< the steepest slope or flight it climbs
  Figure stairs_flipper_deg;  ///< the front flippers raised at least this to mount a flight of stairs
  Figure max_step_m;          ///< the highest edge it drives onto; a higher one stops it as a wall
  Figure max_drop_m;          ///< an edge it drives off higher than this tips it over
  Figure body_cog_m;          ///< the height of the body's centre of mass (the arm stowed)
  Figure arm_mass_kg;         ///< the arm's share of the mass, at the middle of its reach
  Figure tip_warning_m;       ///< the centre of mass this close to tipping: the warning
  Figure grip_reach_m;        ///< the gripper closes on what is this close to its tip
};

/// The figures of a robot type (canonical name); the HD-1's for an unknown one.
const RobotFigures& figures_for(std::string_view robot);

}  // namespace andros::vehicle
