// Files are written atomically, and failures name the path and the reason.
#include "core/output_files.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

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
  fs::remove_all(folder);
}
