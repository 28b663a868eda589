/// \file
/// Writing a file so that nothing is ever half-written, for billiards::io's writers, the programs and
/// billiards-derive. The contents go to a temporary file created in the destination folder
/// with mkstemp (a unique name, O_CREAT | O_EXCL: it never opens an existing file or follows a link
/// planted there), are flushed to disk, and the file is renamed over the destination (rename replaces a
/// link at the destination itself, never what it points to; a device, a FIFO or a socket there is
/// refused, never replaced). Every failure removes the temporary file;
/// so do SIGINT, SIGTERM and SIGHUP while one is open. A run killed outright (SIGKILL) leaves its
/// temporary behind: its name carries the writer's process id, and the next write to the same
/// destination removes the temporaries of processes that no longer exist.
#pragma once

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

namespace billiards::io {

namespace detail {

// The temporary file being written, for the signal handler: a fixed buffer (no allocation in the
// handler), marked valid by `pending`.
inline char pending_path[4096];
inline volatile std::sig_atomic_t pending = 0;

extern "C" inline void remove_pending_and_reraise(int signal_number) {
  if (pending) ::unlink(pending_path);
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);
}

// Installs the handler for SIGINT, SIGTERM and SIGHUP where the program has not set its own.
inline void install_signal_cleanup() {
  static const bool installed = [] {
    for (const int signal_number : {SIGINT, SIGTERM, SIGHUP}) {
      struct sigaction current {};
      if (::sigaction(signal_number, nullptr, &current) == 0 && current.sa_handler == SIG_DFL) {
        struct sigaction cleanup {};
        cleanup.sa_handler = remove_pending_and_reraise;
        sigemptyset(&cleanup.sa_mask);
        ::sigaction(signal_number, &cleanup, nullptr);
      }
    }
    return true;
  }();
  static_cast<void>(installed);
}

/// The prefix of every temporary file for `path`: ".NAME.tmp-".
inline std::string temporary_prefix(const std::filesystem::path& path) {
  return "." + path.filename().string() + ".tmp-";
}

}  // namespace detail

/// Removes the temporary files that earlier writes to `path` left behind when they were killed:
/// regular files (never links) named ".NAME.tmp-PID-XXXXXX" in path's folder whose process PID no
/// longer exists. Errors are ignored: this is housekeeping.
inline void remove_stale_temporaries(const std::filesystem::path& path) {
  namespace fs = std::filesystem;
  const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
  const std::string prefix = detail::temporary_prefix(path);
  std::error_code error;
  for (fs::directory_iterator entry(folder, error), end; !error && entry != end; entry.increment(error)) {
    const std::string name = entry->path().filename().string();
    if (name.compare(0, prefix.size(), prefix) != 0) continue;
    char* after = nullptr;
    const long pid = std::strtol(name.c_str() + prefix.size(), &after, 10);
    if (pid <= 0 || after == nullptr || *after != '-') continue;
    if (::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;  // alive, or not ours to judge
    std::error_code ignored;
    if (fs::is_regular_file(fs::symlink_status(entry->path(), ignored))) fs::remove(entry->path(), ignored);
  }
}

/// A file written atomically in parts (see the top of this file): created as a temporary beside `path`,
/// appended to, and renamed over `path` by commit(). Destroyed uncommitted (an exception on the way),
/// it removes the temporary and leaves `path` as it was. One at a time: the signal cleanup knows one
/// temporary. Every failure throws std::runtime_error naming the path and the reason (the system's,
/// never a stale errno), leaving `path` as it was and no temporary file behind.
class AtomicFile {
 public:
  /// Creates the temporary file beside `path` (std::runtime_error naming the path and why, where it
  /// cannot: a folder, a device, a FIFO or a socket at `path`, or no room).
  explicit AtomicFile(const std::filesystem::path& path) : path_(path) {
    namespace fs = std::filesystem;
    if (path.filename().empty()) throw failure("expected a file name, not a folder", 0);
    std::error_code status_error;
    if (fs::is_directory(fs::status(path, status_error))) throw failure("it is a folder, expected a file", 0);
    // rename would replace a device, a FIFO or a socket with the file (as root, `--svg /dev/full` once
    // replaced the device): only a regular file, a link (replaced, as above) or a new name is written.
    if (const fs::file_status existing = fs::symlink_status(path, status_error);
        fs::exists(existing) && !fs::is_regular_file(existing) && !fs::is_symlink(existing)) {
      throw failure(
          "it is not a regular file (a device, a FIFO or a socket), expected a file to replace or a new name", 0);
    }
    const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
    remove_stale_temporaries(path);
    detail::install_signal_cleanup();
    const std::string pattern =
        (folder / (detail::temporary_prefix(path) + std::to_string(::getpid()) + "-XXXXXX")).string();
    if (pattern.size() >= sizeof(detail::pending_path)) throw failure("the path is too long", ENAMETOOLONG);
    std::vector<char> name(pattern.begin(), pattern.end());
    name.push_back('\0');
    descriptor_ = ::mkstemp(name.data());  // O_CREAT | O_EXCL, mode 0600
    if (descriptor_ < 0) throw failure("cannot create a temporary file in '" + folder.string() + "'", errno);
    temporary_ = name.data();
    std::memcpy(detail::pending_path, temporary_.c_str(), temporary_.size() + 1);
    detail::pending = 1;
  }
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  ~AtomicFile() {
    if (descriptor_ >= 0) ::close(descriptor_);
    if (!temporary_.empty()) {
      ::unlink(temporary_.c_str());
      detail::pending = 0;
    }
  }

  /// Appends `contents` to the temporary file.
  void append(const std::string& contents) {
    std::size_t written = 0;
    while (written < contents.size()) {
      const ssize_t n = ::write(descriptor_, contents.data() + written, contents.size() - written);
      if (n < 0) {
        if (errno == EINTR) continue;
        throw give_up("writing '" + temporary_ + "' failed", errno);
      }
      written += static_cast<std::size_t>(n);
    }
  }

  /// Flushes the temporary file to disk and renames it over the path.
  void commit() {
    // mkstemp creates 0600; the outputs are ordinary files, readable like any other.
    if (::fchmod(descriptor_, 0644) != 0) throw give_up("chmod failed", errno);
    if (::fsync(descriptor_) != 0) throw give_up("fsync failed", errno);
    const int descriptor = descriptor_;
    descriptor_ = -1;
    if (::close(descriptor) != 0) throw give_up("close failed", errno);
    if (std::rename(temporary_.c_str(), path_.c_str()) != 0) throw give_up("rename failed", errno);
    temporary_.clear();
    detail::pending = 0;
  }

 private:
  std::runtime_error failure(const std::string& what, int code) const {
    return std::runtime_error("cannot write '" + path_.string() + "': " + what +
                              (code != 0 ? std::string(": ") + std::strerror(code) : std::string()));
  }
  // The failure, the temporary file closed and removed (the error code read before either).
  std::runtime_error give_up(const std::string& what, int code) {
    const std::runtime_error error = failure(what, code);
    if (descriptor_ >= 0) ::close(descriptor_), descriptor_ = -1;
    ::unlink(temporary_.c_str());
    temporary_.clear();
    detail::pending = 0;
    return error;
  }

  std::filesystem::path path_;
  std::string temporary_;
  int descriptor_ = -1;
};

/// Writes `contents` to `path` atomically (see the top of this file). Throws std::runtime_error
/// naming the path and the reason (the system's, never a stale errno) on any failure, leaving `path`
/// as it was and no temporary file behind.
inline void write_file_atomically(const std::filesystem::path& path, const std::string& contents) {
  AtomicFile file(path);
  file.append(contents);
  file.commit();
}

}  // namespace billiards::io
