#pragma once
// printf-style formatting for the views' fixed-width columns.

#include <cstdarg>
#include <cstdio>
#include <string>

namespace andros::view::detail {

/// The text printf would print (at most 255 bytes). A C variadic function,
/// not a template: the format attribute has the compiler check every call's
/// arguments against its format string (-Wformat).
[[gnu::format(printf, 1, 2)]] inline std::string fmt(const char* format, ...) {
  char buf[256];
  va_list args;
  va_start(args, format);
  std::vsnprintf(buf, sizeof buf, format, args);
  va_end(args);
  return buf;
}

}  // namespace andros::view::detail
