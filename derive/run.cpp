#include "run.hpp"

#include "audit/audit.hpp"
#include "core/output_files.hpp"
#include "emit/emitter.hpp"
#include "emit/read_back.hpp"
#include "emit/validate.hpp"

#include <CLI/CLI.hpp>
#include <billiards_support/cli_checks.hpp>
#include <billiards_support/standard_output.hpp>

#include <algorithm>
#include <exception>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace billiards::derive {

namespace {

namespace fs = std::filesystem;

// One model: derived, validated, written, reported. Returns its exit status.
int run_model(const ModelEntry& entry, const fs::path& folder) {
  std::optional<Derivation> derived;
  try {
    derived = entry.derive();
  } catch (const std::exception& error) {
    std::cerr << "billiards-derive: model " << entry.name << ": the derivation stopped: " << error.what()
              << "\n";
    return exit_claims_failed;
  }
  const Derivation& derivation = *derived;
  std::vector<KernelProblem> problems = validate_kernels(derivation.kernels, derivation.claims);
  const std::vector<KernelProblem> reference =
      validate_kernels(derivation.reference_kernels, derivation.claims);
  problems.insert(problems.end(), reference.begin(), reference.end());

  const ModelInfo& model = derivation.model;
  std::vector<std::string> written;
  try {
    ensure_directory(folder);
    const std::string json_text = audit_json(derivation);
    const auto write = [&](const std::string& relative, const std::string& text) {
      const fs::path path = folder / relative;
      write_file_atomically(path, text);
      written.push_back(path.string());
    };
    write(model.markdown_path, audit_markdown(derivation));
    write(model.json_path, json_text);
    // No header unless the whole model verifies: a failed claim, cited by a kernel or not, or a kernel
    // that is not proven means none is printed. Each header is then read back and proven from its text
    // (emit/read_back.hpp), and only written when every function in it is.
    if (problems.empty() && summarize(derivation.claims).failed == 0) {
      std::vector<std::pair<std::string, std::string>> headers;
      const auto printed = [&](const std::string& path, const std::string& text,
                               const std::vector<Kernel>* kernels) {
        const std::string shipped = entry.edit_printed ? entry.edit_printed(path, text) : text;
        if (kernels != nullptr) {
          const std::vector<KernelProblem> found = prove_printed(shipped, *kernels, derivation.claims);
          problems.insert(problems.end(), found.begin(), found.end());
        }
        headers.emplace_back(path, shipped);
      };
      if (!model.kernels_path.empty())
        printed(model.kernels_path, kernels_header(derivation, json_text), &derivation.kernels);
      if (!model.reference_path.empty())
        printed(model.reference_path, reference_kernels_header(derivation, json_text),
                &derivation.reference_kernels);
      if (!model.kernel_list_path.empty())
        printed(model.kernel_list_path, kernel_list_header(derivation, json_text), nullptr);
      if (problems.empty()) {
        for (const auto& [path, text] : headers) write(path, text);
      }
    }
  } catch (const std::exception& error) {
    std::cerr << "billiards-derive: " << error.what() << "\n";
    return exit_io;
  }
  return report(derivation, problems, written, std::cout, std::cerr) == 0 ? 0 : exit_claims_failed;
}

}  // namespace

int derive_main(int argc, const char* const* argv, const std::vector<ModelEntry>& models) {
  std::string names;
  for (const ModelEntry& entry : models) names += (names.empty() ? "" : ", ") + entry.name;
  CLI::App app{"Re-derives each model (" + names +
                   ") with GiNaC, checks every claim exactly, proves every kernel equal to its claims and "
                   "writes the derivation audit and the kernels.",
               "billiards-derive"};
  std::string out, only;
  app.add_option("--out", out,
                 "Folder to write each model's audit (AUDIT.md, audit.json for the paper) and kernel headers "
                 "(billiards/kernels.hpp, billiards/reference_kernels.hpp) into (created if missing)")
      ->required()
      ->type_name("DIR")
      ->check(billiards_support::path_given("a folder's path"));
  const CLI::Option* model_option =
      app.add_option("--model", only, "Run only this model (one of: " + names + ")")->type_name("NAME");
  app.footer(
      "Exit status: 0 when every claim is verified or an assumption and every kernel is proven, 1 when a "
      "claim failed or a kernel is not proven (each is named on stderr; the audit is still written, the "
      "kernels are not), 2 on a usage error, 3 when an output cannot be written.");
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& help) {
    return app.exit(help);
  } catch (const CLI::ParseError& error) {
    std::cerr << "billiards-derive: " << error.what() << " (run with --help for usage)\n";
    return exit_usage;
  }
  std::vector<const ModelEntry*> chosen;
  for (const ModelEntry& entry : models) {
    if (model_option->count() == 0 || entry.name == only) chosen.push_back(&entry);
  }
  if (chosen.empty()) {
    std::cerr << "billiards-derive: --model: unknown model '" << only << "', expected one of: " << names
              << "\n";
    return exit_usage;
  }
  int status = 0;
  for (const ModelEntry* entry : chosen) {
    const int model_status = run_model(*entry, fs::path(out));
    if (model_status == exit_io) return exit_io;
    status = std::max(status, model_status);
  }
  if (billiards_support::standard_output_failed("billiards-derive")) return exit_io;
  return status;
}

}  // namespace billiards::derive
