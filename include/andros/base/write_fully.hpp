#pragma once
/// Writing a whole text to a descriptor that may be slow or stuck (a log pipe,
/// a paused terminal), from a thread that may wait but must not wait for ever.

#include <string_view>

namespace andros {

/// Writes all of text to fd, waiting (poll) while a non-blocking fd is full,
/// for at most timeout_ms (-1: no limit). Returns 0 when all of it was
/// written, ETIMEDOUT when the time ran out first, else the failed write's errno.
int write_fully(int fd, std::string_view text, int timeout_ms = -1);

}  // namespace andros
