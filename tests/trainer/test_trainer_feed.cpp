// What the trainer's stream says of the operator's pad (docs/trainer.md, "The
// stream"): a game controller's inputs by name, a plain joystick's by number.
#include <gtest/gtest.h>

#include <initializer_list>
#include <nlohmann/json.hpp>

#include "andros/trainer/trainer_feed.hpp"
#include "andros/vehicle/robot_figures.hpp"

namespace andros::trainer {
namespace {

using input::InputEvent;
using input::InputKey;
using input::InputKind;
using nlohmann::json;

InputEvent event(InputEvent::Type type, InputKey key, int value, std::int64_t t_ms = 10) {
  InputEvent e;
  e.t_ms = t_ms;
  e.type = type;
  e.key = key;
  e.value = value;
  return e;
}

/// The pad part of the stream's object after the loop read `input`.
json pad_shown(const input::InputState& input, const input::DeviceLayout* layout) {
  StreamHub hub;
  TrainerFeed feed(vehicle::figures_for("hd1"), hub);
  feed.observe_pad(input, layout);
  LoopFacts facts;
  facts.tick = 1;
  feed.observe(facts);
  feed.advance(1'000'000);
  return json::parse(feed.state_with_trail())["pad"];
}

input::InputState connected(const char* name) {
  input::InputState input;
  auto connect = event(InputEvent::Type::kConnect, {}, 0, 0);
  connect.name = name;
  input.apply(connect);
  return input;
}

TEST(TrainerFeed, APlainJoysticksNumberedButtonsHatsAndAxesAreShown) {
  auto input = connected("Flight Stick");
  input.apply(event(InputEvent::Type::kButton, {InputKind::kJoyButton, 3}, 1));
  input.apply(event(InputEvent::Type::kButton, {InputKind::kJoyButton, 11}, 1));
  input.apply(event(InputEvent::Type::kHat, {InputKind::kHat, 0}, 1));  // SDL_HAT_UP
  input.apply(event(InputEvent::Type::kAxis, {InputKind::kJoyAxis, 1}, -20000));
  input::DeviceLayout stick;  // as SDL opens VirtualDevice::stick: 12 buttons, 4 axes, a hat
  stick.hats = 1;
  for (std::uint16_t i = 0; i < 12; ++i) stick.buttons.push_back({InputKind::kJoyButton, i});
  for (std::uint16_t i = 0; i < 4; ++i) stick.axes.push_back({InputKind::kJoyAxis, i});

  const auto pad = pad_shown(input, &stick);
  EXPECT_EQ(pad["name"], "Flight Stick");
  EXPECT_EQ(pad["buttons"], json({"button 3", "button 11", "hat0up"}));
  EXPECT_EQ(pad["axes"], json({{"axis 0", 0}, {"axis 1", -20000}, {"axis 2", 0}, {"axis 3", 0}}));
}

TEST(TrainerFeed, AGameControllersInputsAreShownByName) {
  auto input = connected("Pad");
  input.apply(event(InputEvent::Type::kButton, {InputKind::kPadButton, 9}, 1));  // leftshoulder
  input.apply(event(InputEvent::Type::kAxis, {InputKind::kPadAxis, 1}, 12000));  // lefty
  input::DeviceLayout pad_layout;
  pad_layout.game_controller = true;

  for (const auto* layout : std::initializer_list<const input::DeviceLayout*>{nullptr, &pad_layout}) {
    const auto pad = pad_shown(input, layout);
    EXPECT_EQ(pad["buttons"], json({"leftshoulder"}));
    EXPECT_EQ(pad["axes"]["lefty"], 12000);
    EXPECT_EQ(pad["axes"].size(), input::kPadAxisNames.size());
  }
}

// Each frame's object shows the pad the loop read for that frame, however
// late the motion thread takes the ticks: here only after the loop has read
// the pad for all four (the second tick's frame not taken by the link: its
// object, sent with no frame, shows the pad read for the next frame).
TEST(TrainerFeed, EachFramesObjectShowsThePadReadForThatFrame) {
  StreamHub hub;
  TrainerFeed feed(vehicle::figures_for("hd1"), hub);
  const auto stream = hub.subscribe();
  auto input = connected("Pad");
  std::int64_t t_ms = 0;
  const auto tick = [&](int lefty, bool sent) {
    input.apply(event(InputEvent::Type::kAxis, {InputKind::kPadAxis, 1}, lefty));
    feed.observe_pad(input, nullptr);
    feed.queue_tick(t_ms, protocol::DataBytes{}, sent);
    t_ms += 40;
    LoopFacts facts;
    facts.sent = sent;
    feed.observe(facts);
  };
  tick(100, true);
  tick(200, false);
  tick(300, true);
  tick(400, true);
  ASSERT_TRUE(feed.take_ticks());

  const auto messages = stream->next(std::chrono::milliseconds(0));
  ASSERT_TRUE(messages);
  std::vector<json> shown;
  for (const auto& m : *messages) shown.push_back(json::parse(*m));
  ASSERT_EQ(shown.size(), 4u);
  const int frame[] = {1, 1, 2, 3};
  const int pad_frame[] = {1, 2, 2, 3};
  const int lefty[] = {100, 300, 300, 400};
  for (std::size_t i = 0; i < shown.size(); ++i) {
    EXPECT_EQ(shown[i]["frame"], frame[i]) << "tick " << i;
    EXPECT_EQ(shown[i]["pad"]["frame"], pad_frame[i]) << "tick " << i;
    EXPECT_EQ(shown[i]["pad"]["axes"]["lefty"], lefty[i]) << "tick " << i;
  }
}

}  // namespace
}  // namespace andros::trainer
