#pragma once
/// Reading mapping files (docs/mapping.md) and finding a robot's file.

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "andros/mapping/model.hpp"

namespace andros::mapping {

/// Loads a mapping file and the chain of files it `extends`, merged, without
/// validate(). Every error is an InputError at FILE:LINE:COL; a bad key or
/// binding does not stop the reading, so that all are reported at once
/// (InputErrors for more than one).
Mapping load_mapping_file(const std::filesystem::path& file);

/// Whether a file loaded must name a robot.
enum class NeedsRobot : std::uint8_t {
  kYes,      ///< a mapping to run (`--mapping FILE`)
  kIfNamed,  ///< `check`: a file with no `robot:` is checked as a base for others to extend
};

/// Loads a mapping from an explicit file (`--mapping FILE`) and validates
/// it. Every error of both steps is reported (InputErrors for more than one):
/// validate() also runs on what could be read when the reading found errors.
ValidMapping load_mapping(const std::filesystem::path& file, NeedsRobot needs = NeedsRobot::kYes);

/// Reads text as the mapping file `file` would be read (its errors name
/// file, its `extends:` is found from there), and validates it; file need
/// not exist. For `learn`, which checks a file before it writes it.
ValidMapping load_mapping_text(const std::string& text, const std::filesystem::path& file);

/// A mapping file as a session recorded it: its path, only a label, and its text.
struct MappingText {
  std::string label;
  std::string text;
};

/// A recorded chain (the mapping first, then each file it extends), read in
/// memory: each `extends:` takes the next file of the chain, whose name must
/// be the one it gives (`extends: hd1`: hd1.yaml; `extends: base/x.yaml`:
/// x.yaml). Nothing is read from or written to the disk; the search path is
/// never asked.
ValidMapping load_recorded_chain(const std::vector<MappingText>& files);

/// Where `--robot NAME` looks, in order: $XDG_CONFIG_HOME/andros-bridge/mappings
/// (default ~/.config/...), the source tree's mappings/ when it exists (not
/// in a package's build), bin/../share/andros-bridge/mappings beside the
/// binary (an installed tree unpacked elsewhere), the installed mappings/.
std::vector<std::filesystem::path> mapping_search_path();

/// The first `<robot in lower case>.yaml` on the search path. Throws
/// InputError for an unknown robot or when no directory has the file.
std::filesystem::path find_robot_mapping(std::string_view robot, const std::vector<std::filesystem::path>& search_path);

/// Finds, loads and validates a robot type's mapping; its `robot` must match.
ValidMapping load_robot_mapping(std::string_view robot);

/// What `--mapping FILE` / `--robot NAME` choose: the file when one is given,
/// else the robot's shipped mapping.
ValidMapping load_chosen_mapping(const std::string& file, std::string_view robot);

}  // namespace andros::mapping
