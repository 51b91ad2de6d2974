#pragma once
/// The trainer's page (docs/trainer.md): one HTML file with its SVG and
/// script inline, compiled into the binary; nothing is fetched from outside.

#include <string_view>

namespace andros::trainer {

std::string_view trainer_page();

}  // namespace andros::trainer
