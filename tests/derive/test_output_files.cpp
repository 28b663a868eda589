// Files are written atomically, and failures name the path and the reason.
#include "core/output_files.hpp"

#include <billiards/io/atomic_file.hpp>

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <csignal>

#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace billiards::derive;

namespace {

std::string read(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream contents;
  contents << in.rdbuf();
  return contents.str();
}

fs::path fresh_folder(const std::string& name) {
  const fs::path folder =
      fs::temp_directory_path() / ("billiards-test-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(folder);
  return folder;
}

}  // namespace

TEST_CASE("Atomic output files", "[derive][files]") {
  const fs::path folder = fresh_folder("files");

  SECTION("a file is written whole, in a folder created on the way, with no temporary left") {
    write_file_atomically(folder / "nested" / "AUDIT.md", "hello\n");
    CHECK(read(folder / "nested" / "AUDIT.md") == "hello\n");
    CHECK(std::distance(fs::directory_iterator(folder / "nested"), fs::directory_iterator()) == 1);
  }
  SECTION("an existing file is replaced") {
    write_file_atomically(folder / "a.txt", "first");
    write_file_atomically(folder / "a.txt", "second");
    CHECK(read(folder / "a.txt") == "second");
  }
  SECTION("a folder that cannot be created is an error naming it") {
    write_file_atomically(folder / "plain", "x");
    try {
      ensure_directory(folder / "plain" / "sub");
      FAIL("no error");
    } catch (const std::runtime_error& error) {
      CHECK(std::string(error.what()).find((folder / "plain" / "sub").string()) != std::string::npos);
    }
  }
  SECTION("a destination that is a folder fails and leaves it as it was") {
    fs::create_directories(folder / "taken");
    CHECK_THROWS_AS(write_file_atomically(folder / "taken", "x"), std::runtime_error);
    CHECK(fs::is_directory(folder / "taken"));
    CHECK(std::distance(fs::directory_iterator(folder), fs::directory_iterator()) == 1);
  }
  SECTION("a link planted at a temporary name or at the destination is never written through") {
    fs::create_directories(folder);
    write_file_atomically(folder / "victim", "precious");
    fs::create_symlink(folder / "victim", folder / "a.txt.tmp");
    fs::create_symlink(folder / "victim", folder / "b.txt");
    write_file_atomically(folder / "a.txt", "new");
    write_file_atomically(folder / "b.txt", "new");
    CHECK(read(folder / "victim") == "precious");
    CHECK(read(folder / "a.txt") == "new");
    CHECK_FALSE(fs::is_symlink(folder / "b.txt"));
  }
  SECTION("a killed run's temporaries are removed by the next write; a live process's are kept") {
    fs::create_directories(folder);
    // pid 999999999 is above any pid_max, so no such process exists; pid 1 always does.
    write_file_atomically(folder / ".audit.json.tmp-999999999-abcdef", "stale");
    write_file_atomically(folder / ".audit.json.tmp-1-abcdef", "someone else's");
    write_file_atomically(folder / "victim", "precious");
    fs::create_symlink(folder / "victim", folder / ".audit.json.tmp-999999998-link");
    write_file_atomically(folder / "audit.json", "{}");
    CHECK_FALSE(fs::exists(folder / ".audit.json.tmp-999999999-abcdef"));
    CHECK(fs::exists(folder / ".audit.json.tmp-1-abcdef"));
    CHECK(fs::is_symlink(folder / ".audit.json.tmp-999999998-link"));  // links are never touched
    CHECK(read(folder / "victim") == "precious");
  }
  SECTION("SIGTERM while a temporary file is open removes it, and the signal still ends the process") {
    fs::create_directories(folder);
    const fs::path temporary = folder / ".out.tmp-pending";
    const pid_t child = ::fork();
    REQUIRE(child >= 0);
    if (child == 0) {
      // Catch has its own SIGTERM handler here, so install_signal_cleanup() (which never replaces a
      // program's handler) would leave it: the child installs the cleanup handler itself.
      std::signal(SIGTERM, billiards::io::detail::remove_pending_and_reraise);
      { std::ofstream(temporary) << "half"; }
      const std::string name = temporary.string();
      std::copy(name.c_str(), name.c_str() + name.size() + 1, billiards::io::detail::pending_path);
      billiards::io::detail::pending = 1;
      std::raise(SIGTERM);
      ::_exit(0);  // not reached
    }
    int status = 0;
    REQUIRE(::waitpid(child, &status, 0) == child);
    CHECK(WIFSIGNALED(status));
    CHECK(WTERMSIG(status) == SIGTERM);
    CHECK_FALSE(fs::exists(temporary));
  }
  fs::remove_all(folder);
}
