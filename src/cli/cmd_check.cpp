// `andros-bridge check FILE...`: load and validate mapping files.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "andros/base/error.hpp"
#include "andros/base/sink_text.hpp"
#include "andros/mapping/loader.hpp"
#include "commands.hpp"

namespace andros::cli {
namespace {

/// Loads, but would surprise the operator: a stick driving drive or pivot with
/// no deadzone must read exactly 0 to count as at rest after the deadman press
/// or a layer change (the rest rule), which a worn stick may never do.
std::vector<std::string> warnings(const mapping::Mapping& mapping) {
  std::vector<std::string> out;
  for (const auto ref : mapping::all_bindings(mapping)) {
    const auto& b = mapping::binding_at(mapping, ref);
    const auto* axis = std::get_if<mapping::AxisBinding>(&b.rule);
    if (axis == nullptr || protocol::info(axis->analog).kind != protocol::SignalKind::kCentred ||
        axis->shape.deadzone > 0)
      continue;
    out.push_back(format_error(b.pos,
                               "no deadzone on the stick driving '" + std::string(protocol::info(axis->analog).name) +
                                   "': after the deadman press or a layer change it acts only once it reads "
                                   "exactly 0 (give it a deadzone, e.g. 0.1)",
                               "warning"));
  }
  return out;
}

/// The signals a binding sets: its signal, pair or analog byte, a weapon, a selector's positions' bits.
std::vector<protocol::SignalId> signals_of(const mapping::Binding& b) {
  std::vector<protocol::SignalId> out;
  if (const auto* x = std::get_if<mapping::ButtonBinding>(&b.rule)) out.push_back(x->signal);
  if (const auto* x = std::get_if<mapping::WeaponBinding>(&b.rule)) out.push_back(x->signal);
  if (const auto* x = std::get_if<mapping::PairBinding>(&b.rule)) out.assign(x->signals.begin(), x->signals.end());
  if (const auto target = mapping::analog_target(b)) out.push_back(*target);
  if (const auto* x = std::get_if<mapping::SelectorBinding>(&b.rule)) {
    for (const auto& position : x->positions) out.insert(out.end(), position.begin(), position.end());
  }
  return out;
}

std::set<protocol::SignalId> bound_signals(const mapping::Mapping& m) {
  std::set<protocol::SignalId> out;
  for (const auto ref : mapping::all_bindings(m)) {
    for (const auto id : signals_of(mapping::binding_at(m, ref))) out.insert(id);
  }
  return out;
}

std::string names(const std::vector<protocol::SignalId>& ids) {
  std::string out;
  for (const auto id : ids) out += (out.empty() ? "'" : "/'") + std::string(protocol::info(id).name) + "'";
  return out;
}

/// A signal the extended file bound and this one leaves on no input (moving
/// rear_art_up to X takes X from tool_on): loads, but the operator lost a
/// function, most likely without meaning to. Said at the binding that took
/// the input, when there is one in this file.
std::vector<std::string> lost_signals(const mapping::Mapping& m) {
  if (m.chain.size() < 2) return {};
  const auto base = mapping::load_mapping_file(m.chain[1]);  // read once already: it loads
  const auto mine = bound_signals(m);
  std::vector<std::string> out;
  for (const auto id : bound_signals(base)) {
    if (mine.contains(id)) continue;
    const auto name = "'" + std::string(protocol::info(id).name) + "'";
    SourcePos at{m.file};
    std::string why = "the file it extends bound it";
    for (const auto ref : mapping::all_bindings(base)) {
      const auto& was = mapping::binding_at(base, ref);
      const auto ids = signals_of(was);
      if (std::find(ids.begin(), ids.end(), id) == ids.end() || was.inputs.empty()) continue;
      const auto& input = was.inputs.front();
      why = "the file it extends bound it to '" + input::input_name(input.key) + "' (" +
            std::filesystem::path(input.pos.file).filename().string() + " line " + std::to_string(input.pos.line) + ")";
      for (const auto now_ref : mapping::all_bindings(m)) {
        const auto& now = mapping::binding_at(m, now_ref);
        const bool takes = std::any_of(now.inputs.begin(), now.inputs.end(),
                                       [&](const mapping::InputUse& u) { return u.key == input.key; });
        if (!takes || now.pos.file != m.file || now_ref.layer != ref.layer) continue;
        at = now.pos;
        why += ", which this binding gives to " + names(signals_of(now));
        break;
      }
      break;
    }
    std::string message = name;
    message.append(" is on no input: ").append(why).append(" (bind it to another input if the vehicle needs it)");
    out.push_back(format_error(at, message, "warning"));
  }
  return out;
}

}  // namespace

void add_check_command(CLI::App& app, int& exit_code) {
  auto files = std::make_shared<std::vector<std::string>>();
  auto* cmd = app.add_subcommand("check",
                                 "Load and validate mapping files: prints 'FILE: ok' for each good one and the\n"
                                 "error (FILE:LINE:COL: error: ...) for each bad one; exits 2 if any is bad.\n"
                                 "A file with no 'robot:' is checked as a base for other files to extend. Warnings\n"
                                 "(FILE:LINE:COL: warning: ...) point at what loads but may surprise: a stick on\n"
                                 "drive or pivot with no deadzone, a signal the extended file bound left on no input.\n"
                                 "They do not change the exit code. Every error of a file is reported, not only the\n"
                                 "first, at the line of the file that has it. A 'center:'\n"
                                 "trim other than 128 is said on the ok line: 'FILE: ok (center 124: drive and\n"
                                 "pivot rest at 124 while enabled; neutral frames carry 128)'.");
  cmd->add_option("FILE", *files, "mapping files (YAML)")->required();
  cmd->callback([files, &exit_code] {
    bool all_ok = true;
    for (const auto& file : *files) {
      try {
        const auto valid = mapping::load_mapping(file, mapping::NeedsRobot::kIfNamed);
        const auto& mapping = *valid;
        std::string notes = mapping.robot ? "" : "a base mapping: no robot";
        if (const auto trim = mapping::center_effect(mapping.center); !trim.empty()) {
          notes += (notes.empty() ? "" : "; ") + trim;
        }
        if (!notes.empty()) notes.insert(0, " (").append(")");
        std::printf("%s: ok%s\n", terminal_text(file).c_str(), notes.c_str());
        std::fflush(stdout);
        for (const auto& w : warnings(mapping)) std::fprintf(stderr, "%s\n", w.c_str());
        for (const auto& w : lost_signals(mapping)) std::fprintf(stderr, "%s\n", w.c_str());
      } catch (const InputError& e) {
        std::fflush(stdout);
        std::fprintf(stderr, "%s\n", e.what());
        all_ok = false;
      }
    }
    std::fflush(stdout);
    exit_code = all_ok ? kExitOk : kExitBadInput;
  });
}

}  // namespace andros::cli
