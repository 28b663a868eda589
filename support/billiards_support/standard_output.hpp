// Whether what a program printed reached its standard output, shared by the programs (internal: not
// installed). A full disk or a closed pipe fails the writes silently until the stream is flushed:
// `billiards-gas > /dev/full` printed nothing and still exited 0.
#pragma once

#include <cstdio>
#include <iostream>

namespace billiards_support {

/// Flushes std::cout and stdout; false when either failed.
inline bool standard_output_written() {
  std::cout.flush();
  const bool stream_ok = static_cast<bool>(std::cout);
  const bool file_ok = std::fflush(stdout) == 0 && std::ferror(stdout) == 0;
  return stream_ok && file_ok;
}

/// standard_output_written(), saying "PROGRAM: cannot write to standard output" on standard error when
/// it is false; the caller then exits with its write-failure status.
inline bool standard_output_failed(const char* program) {
  if (standard_output_written()) return false;
  std::cerr << program << ": cannot write to standard output\n";
  return true;
}

}  // namespace billiards_support
