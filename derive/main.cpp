// billiards-derive: parses the command line and writes the outputs; the work is in derivation.cpp.
#include "audit.hpp"
#include "derivation.hpp"
#include "emitter.hpp"
#include "output_files.hpp"

#include <CLI/CLI.hpp>

#include <exception>
#include <filesystem>
#include <iostream>
#include <string>

namespace {

constexpr int exit_claims_failed = 1;
constexpr int exit_usage = 2;
constexpr int exit_io = 3;

}  // namespace

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  using namespace billiards::derive;

  CLI::App app{std::string("Re-derives ") + paper_citation +
                   " with GiNaC, checks every claim exactly and writes the derivation audit.",
               "billiards-derive"};
  std::string out;
  app.add_option(
         "--out", out,
         "Folder to write AUDIT.md, audit.json, billiards/kernels.hpp and billiards/reference_kernels.hpp "
         "into (created if missing)")
      ->required()
      ->type_name("DIR");
  app.footer(
      "Exit status: 0 when every claim is verified or an assumption, 1 when a claim failed (each "
      "is named with its residual), 2 on a usage error, 3 when an output cannot be written.");
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& help) {
    return app.exit(help);
  } catch (const CLI::ParseError& error) {
    std::cerr << "billiards-derive: " << error.what() << " (run with --help for usage)\n";
    return exit_usage;
  }

  const Derivation derivation = derive_paper();
  const fs::path folder(out);
  const fs::path markdown = folder / "AUDIT.md", json = folder / "audit.json";
  const fs::path kernels = folder / "billiards" / "kernels.hpp";
  const fs::path reference_kernels = folder / "billiards" / "reference_kernels.hpp";
  try {
    ensure_directory(folder);
    const std::string json_text = audit_json(derivation);
    write_file_atomically(markdown, audit_markdown(derivation));
    write_file_atomically(json, json_text);
    write_file_atomically(kernels, kernels_header(derivation, fingerprint(json_text)));
    write_file_atomically(reference_kernels, reference_kernels_header(derivation, fingerprint(json_text)));
  } catch (const std::exception& error) {
    std::cerr << "billiards-derive: " << error.what() << "\n";
    return exit_io;
  }

  const int failed =
      report(derivation, {markdown.string(), json.string(), kernels.string(), reference_kernels.string()},
             std::cout, std::cerr);
  return failed == 0 ? 0 : exit_claims_failed;
}
