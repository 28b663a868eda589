// Writing the outputs: every file goes to a temporary file in its destination folder and is renamed
// into place, so an interrupted run never leaves a half-written audit or header.
#pragma once

#include <filesystem>
#include <string>

namespace billiards::derive {

/// Creates `directory` (and its parents) if missing. Throws std::runtime_error naming the path and
/// the reason when it cannot be created or is not a folder.
void ensure_directory(const std::filesystem::path& directory);

/// Writes `contents` to `path` atomically (billiards::io::write_file_atomically: a uniquely named
/// temporary file in the destination folder, flushed, then renamed; removed on every failure and on
/// SIGINT/SIGTERM/SIGHUP; a killed run's temporaries are removed by the next write). Creates the
/// folder first. Throws std::runtime_error naming the path and the reason on any failure, leaving
/// `path` as it was.
void write_file_atomically(const std::filesystem::path& path, const std::string& contents);

}  // namespace billiards::derive
