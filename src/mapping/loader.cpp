#include "andros/mapping/loader.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <optional>

#include "andros/base/error_list.hpp"
#include "andros/base/text.hpp"
#include "andros/protocol/robots.hpp"
#include "binding_reader.hpp"
#include "file_keys.hpp"
#include "yaml_reader.hpp"

namespace andros::mapping {
namespace {

namespace fs = std::filesystem;
using yaml::Reader;

/// The most files in an `extends` chain (the one loaded and its bases). Each
/// is read by a nested call, so the bound also bounds the stack.
constexpr std::size_t kMaxExtendsChain = 16;

/// The files being read, outermost first, the YAML nodes they may still
/// hold, and the errors found so far in any of them.
struct Chain {
  std::vector<fs::path> files;
  std::size_t node_budget = yaml::kMaxNodes;
  ErrorList errors;
  /// A recorded chain (load_recorded_chain): `extends` takes the next of these, never a file.
  const std::vector<MappingText>* recorded = nullptr;
};

/// Why a mapping file cannot be read, from stat(): missing, not permitted, or
/// not a regular file (a FIFO is never opened: that would wait for a writer).
/// Empty for a regular file.
std::string unreadable(const fs::path& file) {
  struct stat st {};
  if (::stat(file.c_str(), &st) != 0) return std::strerror(errno);
  if (S_ISREG(st.st_mode)) return {};
  if (S_ISDIR(st.st_mode)) return "it is a directory";
  if (S_ISFIFO(st.st_mode)) return "it is a FIFO (a named pipe), not a regular file";
  if (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode)) return "it is a device, not a regular file";
  if (S_ISSOCK(st.st_mode)) return "it is a socket, not a regular file";
  return "it is not a regular file";
}

Mapping read_file(const fs::path& file, Chain& chain, const SourcePos& from, const std::string* text = nullptr);

/// `extends: ROBOT` (a robot's name, no folder): that robot's mapping as
/// `--robot` finds it, passing over the files of this chain, so that
/// ~/.config/andros-bridge/mappings/hd1.yaml may extend the shipped hd1.yaml.
fs::path robot_base(const Reader& r, const YAML::Node& node, std::string_view robot, const Chain& chain) {
  const auto file = to_lower(*protocol::canonical_robot(robot)) + ".yaml";
  std::string looked;
  for (const auto& dir : mapping_search_path()) {
    std::error_code ec;
    auto candidate = dir / file;
    if (!fs::is_regular_file(candidate, ec)) continue;
    if (std::find(chain.files.begin(), chain.files.end(), fs::weakly_canonical(candidate, ec)) != chain.files.end())
      continue;
    return candidate;
  }
  for (const auto& dir : mapping_search_path()) looked += (looked.empty() ? "" : ", ") + dir.string();
  r.fail(node, "'extends: " + std::string(robot) + "': no " + file +
                   " other than this file on the mapping search path (" + looked + ")");
}

/// The recorded file after the one being read, when its name is the one `extends` gives.
Mapping read_recorded_base(const Reader& r, const YAML::Node& node, const std::string& name, Chain& chain) {
  const auto& files = *chain.recorded;
  const std::size_t next = chain.files.size();
  const auto wanted = fs::path(name).filename();
  if (next >= files.size() || fs::path(files[next].label).filename() != wanted) {
    r.fail(node, "'extends: " + name + "': the session recorded no " + quote_name(wanted.string()) +
                     " next in the mapping's chain");
  }
  return read_file(files[next].label, chain, r.pos(node), &files[next].text);
}

void apply_extends(const Reader& r, const YAML::Node& node, const fs::path& file, Chain& chain, Mapping& out) {
  if (chain.files.size() >= kMaxExtendsChain) {
    r.fail(node, "'extends' chain too long: this base would be file " + std::to_string(chain.files.size() + 1) +
                     " of the chain from '" + chain.files.front().filename().string() + "' (at most " +
                     std::to_string(kMaxExtendsChain) + " files)");
  }
  const auto name = r.text(node, "extends");
  const bool robot = name.find('/') == std::string::npos && protocol::canonical_robot(name).has_value();
  if (chain.recorded != nullptr) {
    out = read_recorded_base(r, node, robot ? to_lower(*protocol::canonical_robot(name)) + ".yaml" : name, chain);
    out.robot.reset();
    return;
  }
  const auto base_path = robot ? robot_base(r, node, name, chain) : file.parent_path() / name;
  // The base's values stand unless this file sets them; its robot does not carry over.
  out = read_file(base_path, chain, r.pos(node));
  out.robot.reset();
}

Mapping read_file(const fs::path& file, Chain& chain, const SourcePos& from, const std::string* text) {
  std::error_code ec;
  // A recorded chain's path is a label: never looked at on this machine.
  const auto canonical = chain.recorded != nullptr ? file : fs::weakly_canonical(file, ec);
  if (text == nullptr) {
    if (const auto why = unreadable(file); !why.empty()) {
      throw InputError(from.file.empty() ? SourcePos{file.string()} : from,
                       "cannot open mapping file " + quote_name(file.string()) + ": " + why);
    }
  }
  if (std::find(chain.files.begin(), chain.files.end(), canonical) != chain.files.end()) {
    std::string loop;
    for (const auto& f : chain.files) loop += f.filename().string() + " -> ";
    throw InputError(from, "'extends' makes a cycle: " + loop + canonical.filename().string());
  }
  chain.files.push_back(canonical);
  const Reader r(file.string(), text);
  const YAML::Node root = r.load_document(chain.node_budget);
  r.expect_keys(root,
                {"robot", "extends", "center", "constants", "deadman", "deadman_panic", "estop", "stop_reset",
                 "stop_reset_hold", "enable_timeout", "supervisor", "brake", "scale", "feedback", "bindings", "layers"},
                "a mapping file");
  Mapping m;
  if (root["extends"]) apply_extends(r, root["extends"], file, chain, m);
  m.file = file.string();
  m.chain.insert(m.chain.begin(), canonical.string());
  // Each key and each binding on its own: an error in one is collected and the
  // rest is still read, so that every error is reported at once.
  auto& errors = chain.errors;
  read_file_keys(r, root, m, errors);
  if (const auto b = root["bindings"]) errors.attempt([&] { read_bindings(r, b, m.bindings, errors); });
  if (const auto layers = root["layers"]) errors.attempt([&] { read_layers(r, layers, m.layers, errors); });
  chain.files.pop_back();
  return m;
}

}  // namespace

Mapping load_mapping_file(const fs::path& file) {
  Chain chain;
  std::optional<Mapping> mapping;
  try {
    mapping = read_file(file, chain, SourcePos{});
  } catch (const InputError& e) {
    chain.errors.add(e);  // one that ends the reading (bad YAML, a missing base), after those collected
  }
  chain.errors.throw_if_any();
  return std::move(*mapping);
}

ValidMapping load_mapping(const fs::path& file, NeedsRobot needs) {
  Chain chain;
  std::optional<Mapping> mapping;
  try {
    mapping = read_file(file, chain, SourcePos{});
  } catch (const InputError& e) {
    chain.errors.add(e);
  }
  if (mapping) {
    // After errors in the reading, a key that could not be read would be
    // called missing: the robot and deadman are not asked for then.
    const bool named = needs == NeedsRobot::kYes || mapping->robot.has_value();
    try {
      auto valid = validate(std::move(*mapping), named && chain.errors.empty());
      if (chain.errors.empty()) return valid;
    } catch (const InputError& e) {
      chain.errors.add(e);
    }
  }
  chain.errors.throw_if_any();
  throw InputError(SourcePos{file.string()}, "cannot load the mapping");  // not reached: no mapping came with an error
}

ValidMapping load_recorded_chain(const std::vector<MappingText>& files) {
  if (files.empty()) throw InputError("no mapping file recorded");
  Chain chain;
  chain.recorded = &files;
  return validate(read_file(files.front().label, chain, SourcePos{}, &files.front().text), true);
}

ValidMapping load_mapping_text(const std::string& text, const fs::path& file) {
  Chain chain;
  return validate(read_file(file, chain, SourcePos{}, &text), true);
}

}  // namespace andros::mapping
