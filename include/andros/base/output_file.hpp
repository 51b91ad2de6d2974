#pragma once
/// The one way a command writes its output file (`sheet`, `learn`, `replay`
/// and `record` --output), so that a failure never costs what was there:
///
/// - `-` is standard output (never a file named `-`: write `./-` for that);
/// - a device node, FIFO or socket (the path, or where its links lead) is
///   written in place: never truncated by us, removed or replaced; a FIFO
///   that gets no reader within 5 s is refused (`cannot open 'PATH' for
///   writing: a FIFO that no reader opened in 5 s`), never waited on for ever;
/// - anything else (a regular file, or nothing yet) is written to a temporary
///   file beside it (`.NAME.XXXXXX`), which commit() renames over it: the old
///   file stays whole until then, and keeps its mode (and its owner, where
///   the process may give it);
/// - a symbolic link is followed: its target is replaced and the link kept; a
///   dangling link's target is created;
/// - a live output (record's script) that makes a new file makes it in
///   place, so that it grows where it is seen and a killed recording keeps
///   what it saw; an existing file is still replaced only at commit();
/// - on any error the old file is untouched, the temporary removed, nothing
///   else removed, and the RuntimeError says why: `cannot open 'PATH' for
///   writing: Permission denied`, `cannot write 'PATH': No space left on device`.

#include <sys/stat.h>

#include <cstdint>
#include <ostream>
#include <streambuf>
#include <string>
#include <string_view>

namespace andros {

/// Writes all of text to fd: 0, or the errno of the failure (write_fully's
/// contract). A test gives one that fails on purpose.
using WriteFn = int (*)(int fd, std::string_view text);

class OutputFile {
 public:
  /// A new file: made at commit() (whole or not at all), or as written (a live recording).
  enum class NewFile : std::uint8_t { kAtCommit, kAsWritten };

  /// Opens path for writing as above. write_fn: nullptr for write_fully().
  explicit OutputFile(std::string path, WriteFn write_fn = nullptr, NewFile new_file = NewFile::kAtCommit);
  /// Without commit(): the temporary is removed and the target left as it was.
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  /// Appends text (buffered). Throws RuntimeError `cannot write 'PATH': REASON`.
  void write(std::string_view text);
  /// The same file as a stream, for code that writes one (replay's frames,
  /// record's events): a failed write sets badbit, and commit() throws with
  /// the reason.
  std::ostream& stream() { return stream_; }
  /// Writes out what is buffered (a recording's events as they come). False
  /// on failure; commit() then throws with the reason.
  bool flush();
  /// Throws the first failed write's RuntimeError, if one failed.
  void check() const;
  /// Writes out the rest and ends the file: a temporary's data is synced and
  /// renamed over the target. Throws RuntimeError on any failure, with the
  /// temporary removed and the target as it was.
  void commit();

  /// The path as given (`-` for standard output).
  [[nodiscard]] const std::string& path() const { return path_; }
  /// How messages name it: the path quoted, or "standard output".
  [[nodiscard]] std::string display() const;
  /// True when written through a temporary file renamed at commit().
  [[nodiscard]] bool replaces() const { return !temporary_.empty(); }

 private:
  class Buffer : public std::streambuf {
   public:
    explicit Buffer(OutputFile& file) : file_(file) {}

   protected:
    int_type overflow(int_type c) override;
    std::streamsize xsputn(const char* s, std::streamsize n) override;
    int sync() override;

   private:
    OutputFile& file_;
  };

  bool put(std::string_view text);
  [[noreturn]] void fail_write(int error) const;
  void open_temporary(const std::string& target, const struct stat* old);

  std::string path_;
  WriteFn write_;
  int fd_ = -1;
  bool own_fd_ = false;    ///< false for standard output
  std::string target_;     ///< the file a temporary replaces (links followed)
  std::string temporary_;  ///< empty: written in place
  std::string pending_;    ///< written, not yet handed to the descriptor
  int error_ = 0;          ///< the first failed write's errno
  bool committed_ = false;
  Buffer buffer_{*this};
  std::ostream stream_{&buffer_};
};

/// Writes text to path as a whole: OutputFile, write, commit.
void write_output_file(const std::string& path, std::string_view text, WriteFn write = nullptr);

}  // namespace andros
