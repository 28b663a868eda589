#include "core/output_files.hpp"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <system_error>
#include <vector>

#include <sys/stat.h>
#include <unistd.h>

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
  const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
  ensure_directory(folder);
  // mkstemp in the destination folder: the rename below then stays on one file system.
  std::string pattern = (folder / ("." + path.filename().string() + ".tmp-XXXXXX")).string();
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  const int descriptor = ::mkstemp(name.data());
  if (descriptor < 0) {
    throw std::runtime_error("cannot write '" + path.string() + "': " + std::strerror(errno));
  }
  const std::string temporary(name.data());
  const auto fail = [&](const std::string& what) {
    const std::string reason = std::strerror(errno);
    ::close(descriptor);
    ::unlink(temporary.c_str());
    throw std::runtime_error("cannot write '" + path.string() + "': " + what + ": " + reason);
  };
  std::size_t written = 0;
  while (written < contents.size()) {
    const ssize_t n = ::write(descriptor, contents.data() + written, contents.size() - written);
    if (n < 0) {
      if (errno == EINTR) continue;
      fail("write failed");
    }
    written += static_cast<std::size_t>(n);
  }
  // mkstemp creates 0600; outputs are ordinary files, readable like any other.
  if (::fchmod(descriptor, 0644) != 0) fail("chmod failed");
  if (::fsync(descriptor) != 0) fail("fsync failed");
  if (::close(descriptor) != 0) {
    const std::string reason = std::strerror(errno);
    ::unlink(temporary.c_str());
    throw std::runtime_error("cannot write '" + path.string() + "': close failed: " + reason);
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    ::unlink(temporary.c_str());
    throw std::runtime_error("cannot write '" + path.string() + "': rename failed: " + reason);
  }
}

}  // namespace billiards::derive
