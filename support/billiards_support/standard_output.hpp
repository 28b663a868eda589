// Whether what a program printed reached its standard output, shared by the programs (internal: not
// installed). A full disk or a closed pipe fails the writes silently until the stream is flushed:
// `billiards-gas > /dev/full` printed nothing and still exited 0.
#pragma once

#include <cstdio>
#include <iostream>

namespace billiards_support {

/// Flushes std::cout and stdout; false when either failed. On false the program should say
/// "cannot write to standard output" on standard error and exit with its write-failure status.
inline bool standard_output_written() {
  std::cout.flush();
  const bool stream_ok = static_cast<bool>(std::cout);
  const bool file_ok = std::fflush(stdout) == 0 && std::ferror(stdout) == 0;
  return stream_ok && file_ok;
}

}  // namespace billiards_support
