// The plot an investigator reads (view/plot.hpp): a colour for each state (a
// stop's by whose, shutdown apart), named in the legend when used and only
// then; who reset a stop; the weapons layer in the weapons red; a lane for
// each fact the input gives, from a script's events or a session's records.
#include <gtest/gtest.h>
#include <spdlog/fmt/fmt.h>

#include <map>
#include <set>
#include <string>

#include "andros/input/events.hpp"
#include "andros/mapping/loader.hpp"
#include "andros/view/plot.hpp"

namespace andros::view {
namespace {

bool has(const std::string& svg, const std::string& text) { return svg.find(text) != std::string::npos; }

/// A sample a tick (40 ms apart) in each state given.
PlotInput states(const std::vector<std::pair<run::OpState, std::string>>& seq) {
  PlotInput in;
  std::int64_t t = 0;
  for (const auto& [state, stop] : seq) {
    PlotSample p;
    p.t_ms = t;
    p.state = state;
    p.stop = stop;
    in.samples.push_back(p);
    t += 40;
  }
  return in;
}

/// A legend entry: its swatch (rect) in colour, then its name.
bool legend_names(const std::string& svg, const std::string& name, const std::string& colour) {
  const auto at = svg.find(" font-size=\"9\">" + name + "</text>");
  if (at == std::string::npos) return false;
  const auto swatch = svg.rfind("<rect", at);
  return swatch != std::string::npos && svg.find("fill=\"" + colour + "\"", swatch) < at;
}

TEST(PlotColours, EachStateHasItsOwnColourNamedInTheLegend) {
  using S = run::OpState;
  const auto svg = render_plot_svg(states({{S::kNoLink, ""},
                                           {S::kNoController, ""},
                                           {S::kNotEnabled, ""},
                                           {S::kEnabled, ""},
                                           {S::kStopped, "operator"},
                                           {S::kStopped, "supervisor"},
                                           {S::kStopped, "frame gate"},
                                           {S::kSuspended, ""},
                                           {S::kReloading, ""},
                                           {S::kShuttingDown, ""}}));
  const std::vector<std::pair<std::string, std::string>> want = {{"no link", "#ffb74d"},
                                                                 {"no controller", "#fdd835"},
                                                                 {"not enabled", "#c9c9c9"},
                                                                 {"enabled", "#4caf50"},
                                                                 {"stopped by the operator", "#e57373"},
                                                                 {"stopped by the supervisor", "#d81b60"},
                                                                 {"stopped by the frame gate", "#880e4f"},
                                                                 {"suspended (Ctrl-Z)", "#90a4ae"},
                                                                 {"reloading", "#64b5f6"},
                                                                 {"shutting down", "#424242"}};
  std::set<std::string> colours;
  for (const auto& [name, colour] : want) {
    EXPECT_TRUE(legend_names(svg, name, colour)) << name << " " << colour;
    // The band: a rect of the colour, the band's height (20).
    EXPECT_TRUE(has(svg, "height=\"20.0\" fill=\"" + colour + "\"")) << colour;
    colours.insert(colour);
  }
  EXPECT_EQ(colours.size(), want.size()) << "two states share a colour";
}

TEST(PlotColours, TheLegendNamesOnlyTheColoursUsed) {
  using S = run::OpState;
  const auto svg = render_plot_svg(states({{S::kNotEnabled, ""}, {S::kEnabled, ""}, {S::kNotEnabled, ""}}));
  EXPECT_TRUE(legend_names(svg, "not enabled", "#c9c9c9"));
  EXPECT_TRUE(legend_names(svg, "enabled", "#4caf50"));
  for (const char* unused : {"no link", "no controller", "stopped by the operator", "shutting down", "reloading"}) {
    EXPECT_FALSE(has(svg, std::string(">") + unused + "<")) << unused;
  }
}

TEST(PlotColours, ALostControllerIsNotNotEnabledAndShutdownIsNotAStop) {
  using S = run::OpState;
  const auto lost = render_plot_svg(states({{S::kNoController, ""}, {S::kNoController, ""}}));
  EXPECT_FALSE(has(lost, "#c9c9c9")) << "drawn as not enabled";
  const auto end = render_plot_svg(states({{S::kShuttingDown, ""}, {S::kShuttingDown, ""}}));
  EXPECT_FALSE(has(end, "#e57373")) << "drawn as stopped";
  EXPECT_TRUE(has(end, ">shutting down<"));
}

TEST(PlotColours, WhoResetAStopIsSaidWhereItWasReset) {
  run::TickReport r;
  r.state = run::OpState::kStopped;
  r.stopped_by = run::StopBy::kSupervisor;
  PlotInput in;
  in.samples.push_back(plot_sample(r));
  r.t_ms = 40;
  r.state = run::OpState::kNotEnabled;
  r.stopped_by.reset();
  r.reset_by = run::StopBy::kSupervisor;
  in.samples.push_back(plot_sample(r));
  EXPECT_EQ(in.samples[1].reset, "supervisor");
  EXPECT_TRUE(has(render_plot_svg(in), ">reset by the supervisor<"));

  // From a session's records: the reset record says who, until the next enable.
  record::Session s;
  s.settings.rate_millihertz = 25'000;
  s.frames.emplace_back();
  s.states = {{0, run::OpState::kStopped}, {40, run::OpState::kNotEnabled}, {120, run::OpState::kEnabled}};
  s.stops = {{.t_ms = 0, .reset = false, .by = run::StopBy::kGate, .name = ""},
             {.t_ms = 40, .reset = true, .by = run::StopBy::kOperator, .name = ""}};
  s.end.emplace();
  s.end->t_ms = 160;
  s.end->last_tick = 4;
  const auto samples = plot_samples(s);
  ASSERT_EQ(samples.size(), 5U);
  EXPECT_EQ(samples[0].stop, "frame gate");
  EXPECT_EQ(samples[1].reset, "operator");
  EXPECT_EQ(samples[2].reset, "operator");
  EXPECT_EQ(samples[3].reset, "");  // enabled at 120
}

TEST(PlotColours, TheWeaponsLayerIsInTheWeaponsRed) {
  PlotInput in;
  for (const char* layer : {"", "weapons", "camera", ""}) {
    PlotSample p;
    p.t_ms = static_cast<std::int64_t>(in.samples.size()) * 1000;
    p.layer = layer;
    in.samples.push_back(p);
  }
  in.weapon_layers = {"weapons"};
  const auto svg = render_plot_svg(in);
  EXPECT_TRUE(has(svg, "<rect x=\"465.0\" y=\"128.0\" width=\"315.00\" height=\"14.0\" fill=\"#b71c1c\">")) << svg;
  EXPECT_TRUE(has(svg, "<rect x=\"780.0\" y=\"128.0\" width=\"315.00\" height=\"14.0\" fill=\"#9575cd\">"));
  EXPECT_TRUE(legend_names(svg, "weapons layer", "#b71c1c"));
  EXPECT_TRUE(legend_names(svg, "other layer", "#9575cd"));
}

constexpr const char* kMapping = R"(robot: HD1
deadman: lefttrigger
estop: guide
supervisor: {stop: guide, weapons_consent: a}
bindings:
  - signal: front_art_up
    button: dpup
layers:
  weapons:
    hold: rightshoulder
    bindings:
      - signal: weapon_1
        button: b
        arm: leftshoulder
)";

/// Where each lane was on, as "from-to" spans (-1: to the end).
std::map<LaneKind, std::string> spans(const std::vector<PlotLane>& lanes) {
  std::map<LaneKind, std::string> out;
  for (const auto& l : lanes) {
    std::string s;
    for (const auto& span : l.spans) s += std::to_string(span.from_ms) + "-" + std::to_string(span.to_ms) + " ";
    out[l.kind] = s;
  }
  return out;
}

constexpr const char* kScript = R"(0 connect Operator
0 supervisor connect Supervisor
100 axis lefttrigger 10000
200 axis lefttrigger 30000
300 button leftshoulder 1
400 supervisor button a 1
500 button guide 1
600 supervisor button guide 1
700 button guide 0
800 supervisor button guide 0
900 supervisor button a 0
1000 button leftshoulder 0
1100 disconnect
1200 supervisor disconnect
1300 connect Operator
1400 supervisor connect Supervisor
)";

TEST(PlotLanes, EachLaneIsWhatTheInputDidReadWithTheMapping) {
  const auto m = mapping::load_mapping_text(kMapping, "lanes.yaml");
  LaneBuilder b(*m, true);
  for (const auto& e : input::parse_event_script(kScript, "lanes.events")) b.event(e);
  b.link(1500, false);
  b.link(1600, true);
  const auto got = spans(b.lanes());
  ASSERT_EQ(got.size(), 8U);
  EXPECT_EQ(got.at(LaneKind::kOperatorPad), "0-1100 1300--1 ");
  EXPECT_EQ(got.at(LaneKind::kSupervisorPad), "0-1200 1400--1 ");
  EXPECT_EQ(got.at(LaneKind::kLink), "0-1500 1600--1 ");
  EXPECT_EQ(got.at(LaneKind::kDeadman), "200-1100 ");  // the trigger past its press point, until the pad was lost
  EXPECT_EQ(got.at(LaneKind::kOperatorStop), "500-700 ");
  EXPECT_EQ(got.at(LaneKind::kSupervisorStop), "600-800 ");
  EXPECT_EQ(got.at(LaneKind::kConsent), "400-900 ");
  EXPECT_EQ(got.at(LaneKind::kArming), "300-1000 ");
  EXPECT_EQ(weapon_layers(*m), std::vector<std::string>{"weapons"});

  // Unsupervised, and a mapping with no stop button or arming: those lanes are not drawn.
  const auto plain = mapping::load_mapping_text("robot: HD1\ndeadman: leftshoulder\n", "plain.yaml");
  const auto few = spans(LaneBuilder(*plain, false).lanes());
  EXPECT_EQ(few.size(), 3U);
  EXPECT_TRUE(few.contains(LaneKind::kDeadman) && few.contains(LaneKind::kOperatorPad) &&
              few.contains(LaneKind::kLink));
}

TEST(PlotLanes, EachLaneIsDrawnNamedInItsColour) {
  PlotInput in = states({{run::OpState::kEnabled, ""}, {run::OpState::kEnabled, ""}});
  const std::vector<std::pair<std::string, std::string>> want = {{"controller (operator)", "#607d8b"},
                                                                 {"controller (supervisor)", "#8d6e63"},
                                                                 {"link up", "#00897b"},
                                                                 {"deadman held", "#2e7d32"},
                                                                 {"stop button (operator)", "#e57373"},
                                                                 {"stop button (supervisor)", "#d81b60"},
                                                                 {"consent (supervisor)", "#f9a825"},
                                                                 {"arming input held", "#e65100"}};
  for (std::size_t i = 0; i < want.size(); ++i) {
    in.lanes.push_back(PlotLane{static_cast<LaneKind>(i), {PlotSpan{0, 40}}});
  }
  const auto svg = render_plot_svg(in);
  for (std::size_t i = 0; i < want.size(); ++i) {
    const auto& [name, colour] = want[i];
    const double y = 148 + 11 * static_cast<double>(i);
    EXPECT_TRUE(has(svg, ">" + name + "</text>")) << name;
    EXPECT_TRUE(has(
        svg, fmt::format("<rect x=\"150.0\" y=\"{:.1f}\" width=\"945.00\" height=\"9.0\" fill=\"{}\">", y + 1, colour)))
        << name << "\n"
        << svg;
  }
}

TEST(PlotLanes, ASessionsLanesComeFromItsRecordedMappingAndLinkRecords) {
  record::Session s;
  s.settings.rate_millihertz = 25'000;
  s.settings.supervised = true;
  s.settings.sources = {{"/somewhere/lanes.yaml", kMapping}};
  s.events = input::parse_event_script(kScript, "lanes.events");
  for (const auto& [t, up] :
       std::vector<std::pair<std::int64_t, bool>>{{-1, false}, {0, true}, {1500, false}, {1600, true}}) {
    record::LinkRecord l;
    l.t_ms = t;
    l.state = up ? link::LinkState::kUp : link::LinkState::kConnecting;
    s.links.push_back(l);
  }
  PlotInput in;
  add_lanes(in, s);
  const auto got = spans(in.lanes);
  EXPECT_EQ(got.at(LaneKind::kLink), "0-1500 1600--1 ");
  EXPECT_EQ(got.at(LaneKind::kDeadman), "200-1100 ");
  EXPECT_EQ(got.at(LaneKind::kConsent), "400-900 ");
  EXPECT_EQ(in.weapon_layers, std::vector<std::string>{"weapons"});

  // A recorded mapping that does not load: no lanes, and the page says why.
  s.settings.sources = {{"/somewhere/bad.yaml", "robot: HD1\n"}};
  PlotInput bad;
  add_lanes(bad, s);
  EXPECT_TRUE(bad.lanes.empty());
  EXPECT_TRUE(has(render_plot_svg(bad), "no lanes: the recorded mapping cannot be read"));
}

}  // namespace
}  // namespace andros::view
