#pragma once
// printf-style formatting for the views' fixed-width columns.

#include <cstdio>
#include <string>

namespace andros::view::detail {

/// The text printf would print (at most 255 bytes).
std::string fmt(const char* format, auto... args) {
  char buf[256];
  std::snprintf(buf, sizeof buf, format, args...);
  return buf;
}

}  // namespace andros::view::detail
