#pragma once
/// Small value parsers shared by the command line, the config file, the
/// event scripts and the mappings, so that every surface accepts the same text.

#include <cstdint>
#include <string_view>

#include "andros/base/error.hpp"

namespace andros {

/// The dip-switch code: one or two hex digits, an optional 0x prefix ("01",
/// "3C", "0x3c"). Throws InputError at pos.
std::uint8_t parse_code(std::string_view text, const SourcePos& pos);

/// A whole decimal number in [min, max]. Throws InputError at pos naming what.
long long parse_integer(std::string_view text, long long min, long long max, std::string_view what,
                        const SourcePos& pos);

}  // namespace andros
