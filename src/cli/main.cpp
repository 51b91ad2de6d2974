// andros-bridge: a gamepad in, the Andros switchbox's serial frames out.
#include "program.hpp"

int main(int argc, char** argv) { return andros::cli::program_main(argc, argv); }
