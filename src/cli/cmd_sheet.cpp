// `andros-bridge sheet`: the cheat sheet of a mapping, as SVG or text.
#include <memory>
#include <string>

#include "andros/base/error.hpp"
#include "andros/base/output_file.hpp"
#include "andros/mapping/loader.hpp"
#include "andros/protocol/robots.hpp"
#include "andros/view/sheet.hpp"
#include "commands.hpp"

namespace andros::cli {
namespace {

struct SheetOptions {
  std::string robot;
  std::string mapping;
  std::string format = "svg";
  std::string output;
};

void run_sheet(const SheetOptions& opt) {
  if (!opt.robot.empty() && !opt.mapping.empty()) throw InputError("sheet: give --robot or --mapping, not both");
  const auto format = view::parse_sheet_format(opt.format, SourcePos{"--format"});
  const auto mapping =
      mapping::load_chosen_mapping(opt.mapping, opt.robot.empty() ? protocol::kDefaultRobot : opt.robot);
  const auto sheet = view::build_sheet(*mapping);
  const auto text = format == view::SheetFormat::kSvg ? view::render_sheet_svg(sheet) : view::render_sheet_text(sheet);
  write_output_file(opt.output.empty() ? "-" : opt.output, text);  // made whole before FILE is opened
}

}  // namespace

void add_sheet_command(CLI::App& app, int& exit_code) {
  auto opt = std::make_shared<SheetOptions>();
  auto* cmd = app.add_subcommand("sheet",
                                 "Print a mapping's cheat sheet: every input of the pad and what it does, one panel\n"
                                 "per layer, with the deadman, layer keys, arming input, toggles, knobs and\n"
                                 "selectors marked and weapons shown with what they need. SVG is one 190 x 260 mm\n"
                                 "page that prints at 100% on A4 or Letter; text is a table per layer. Made from\n"
                                 "the mapping itself, so it always matches it (docs/sheets.md).");
  cmd->add_option("--robot", opt->robot,
                  "robot type (" + protocol::robot_list() + ", any case; HD-1 and V-A1 too); default HD1");
  cmd->add_option("--mapping", opt->mapping, "mapping file to draw instead of a robot's shipped one");
  cmd->add_option("--format", opt->format, "svg (a printable page) or text (tables for a terminal)")
      ->type_name("svg|text")
      ->default_str("svg");
  cmd->add_option("--output", opt->output,
                  "write to FILE instead of standard output (- is standard output); a failed\n"
                  "write leaves FILE as it was (docs/running.md, Output files)")
      ->type_name("FILE");
  cmd->callback([opt, &exit_code] {
    run_sheet(*opt);
    exit_code = kExitOk;
  });
}

}  // namespace andros::cli
