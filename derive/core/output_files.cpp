#include "core/output_files.hpp"

#include <billiards/io/atomic_file.hpp>

#include <stdexcept>
#include <system_error>

namespace billiards::derive {

namespace fs = std::filesystem;

void ensure_directory(const fs::path& directory) {
  std::error_code error;
  fs::create_directories(directory, error);
  if (error) {
    throw std::runtime_error("cannot create output folder '" + directory.string() + "': " + error.message());
  }
  if (!fs::is_directory(directory)) {
    throw std::runtime_error("output path '" + directory.string() + "' exists and is not a folder");
  }
}

void write_file_atomically(const fs::path& path, const std::string& contents) {
  ensure_directory(path.has_parent_path() ? path.parent_path() : fs::path("."));
  billiards::io::write_file_atomically(path, contents);
}

}  // namespace billiards::derive
