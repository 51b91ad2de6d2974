#pragma once
// A fuzz target's private folder in the temporary directory, named by the
// target and the process: made on first use, removed with everything in it
// when the process ends (libFuzzer's time limit ends it with exit(), which
// runs this destructor; a crash leaves it, next to the crash's input).
#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>

namespace andros::fuzz {

class ScratchDir {
 public:
  explicit ScratchDir(const std::string& target)
      : path_(std::filesystem::temp_directory_path() / ("andros-fuzz-" + target + "-" + std::to_string(::getpid()))) {
    std::filesystem::create_directories(path_);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  ~ScratchDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace andros::fuzz
