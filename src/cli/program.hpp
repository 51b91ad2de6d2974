#pragma once
/// The program's entry, apart from main() (main.cpp) so that it is compiled in
/// the cli stage's unity groups (src/CMakeLists.txt): main.cpp does not include
/// CLI11, whose header alone costs a file 5-15 s of compile time.

namespace andros::cli {

/// Installs the log, parses the command line (which runs the chosen command)
/// and returns the exit code; what escapes is one line on stderr and code 1.
int program_main(int argc, char** argv);

}  // namespace andros::cli
