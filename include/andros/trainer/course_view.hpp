#pragma once
/// The course as the page draws it (docs/trainer.md, "The stream"): its map
/// once (GET /state's `course_map`), and what the vehicle met on it with
/// each frame (the stream's `course`).

#include <nlohmann/json.hpp>

#include "andros/vehicle/vehicle_model.hpp"

namespace andros::trainer {

/// v rounded to three decimals (a millimetre, a thousandth of a radian): how
/// the stream, the state and the replay write the model's numbers.
double r3(double v);

/// The course's geometry: ground, blocks, slopes, landings, door, package, gates, finish, target.
nlohmann::json course_map_json(const vehicle::Course& course);
/// What the vehicle met on its course now (null on open ground).
nlohmann::json course_state_json(const vehicle::VehicleModel& model);

}  // namespace andros::trainer
