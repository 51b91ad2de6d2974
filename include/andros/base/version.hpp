#pragma once

// The version, and the folders this build looks in for mappings. Their values
// come from the build's configuration (src/base/version.cpp.in, written by
// CMake): a build whose folders differ (the Debian package's, another clone's)
// compiles that one small file again, not every file that reads them.
namespace andros {
extern const char* const kVersion;
/// This source tree's mappings/ folder, or "" (a package's build: ANDROS_SOURCE_MAPPINGS=OFF).
extern const char* const kSourceMappingsDir;
extern const char* const kInstalledMappingsDir;
/// kInstalledMappingsDir relative to the binary's own directory.
extern const char* const kMappingsFromBinDir;
}  // namespace andros
