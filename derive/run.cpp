#include "run.hpp"

#include "audit/audit.hpp"
#include "core/output_files.hpp"
#include "emit/emitter.hpp"
#include "emit/validate.hpp"
#include "prove/read_back.hpp"

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

// One model: derived, validated, written, reported. Returns its exit status. The support header, the same
// for every model, is written with the first model whose headers are (`support_written`).
int run_model(const ModelEntry& entry, const fs::path& folder, const std::vector<CanaryOutcome>& canaries,
              bool& support_written) {
  std::optional<Derivation> derived;
  try {
    derived = entry.derive();
  } catch (const std::exception& error) {
    std::cerr << "billiards-derive: model " << entry.name << ": the derivation stopped: " << error.what()
              << "\n";
    return exit_claims_failed;
  }
  Derivation& derivation = *derived;
  derivation.canaries = canaries;
  std::vector<KernelProblem> problems = validate_kernels(derivation.kernels, derivation.claims);
  const std::vector<KernelProblem> reference =
      validate_kernels(derivation.reference_kernels, derivation.claims);
  problems.insert(problems.end(), reference.begin(), reference.end());
  const ModelInfo& model = derivation.model;

  // The headers as they ship (for the mutation suite, with its edit of the printed text), each with the
  // kernels printed into it.
  struct Header {
    std::string path, text;
    const std::vector<Kernel>* kernels;
  };
  const auto headers = [&](const std::string& audit_text) {
    std::vector<Header> out;
    const auto add = [&](const std::string& path, const std::string& text,
                         const std::vector<Kernel>* kernels) {
      if (!path.empty())
        out.push_back({path, entry.edit_printed ? entry.edit_printed(path, text) : text, kernels});
    };
    add(kernel_support_path, kernel_support_header(), nullptr);
    add(model.kernels_path, kernels_header(derivation, audit_text), &derivation.kernels);
    add(model.reference_path, reference_kernels_header(derivation, audit_text),
        &derivation.reference_kernels);
    add(model.kernel_list_path, kernel_list_header(derivation, audit_text), nullptr);
    return out;
  };
  // No header unless the whole model verifies: a failed claim, cited by a kernel or not, or a kernel that
  // is not proven means none is printed. Each header is then read back and proven from its text
  // (prove/read_back.hpp), its plain forms' domains by Gappa, before the audit is written, which shows what
  // Gappa proved; the headers, whose fingerprint covers the audit, are then printed again with it.
  // Every kernel (the reference kernels aside) has a proven error bound: it states where.
  for (const Kernel& kernel : derivation.kernels) {
    if (kernel.domain.empty() && kernel.rounding_cases.empty())
      problems.push_back(
          {kernel.name, kernel.equals,
           "no rounding bound: it states neither a domain nor the cases its rounding is proven "
           "over"});
  }
  // A prover that answered a canary wrongly proves nothing: the kernels are left unproven.
  for (const CanaryOutcome& canary : canaries) {
    if (!canary.as_expected())
      problems.push_back({"(the prover)", "",
                          "its canary " + canary.id + " answered `" + canary.answered + "`, not `" +
                              canary.expected + "`: no kernel is proven by it"});
  }
  const bool verified = problems.empty() && summarize(derivation.claims).failed == 0;
  if (verified) {
    // The kernels are read with the helpers they call: the support header's text, as printed, first.
    const std::vector<Header> printed = headers("");
    const std::string support = std::find_if(printed.begin(), printed.end(), [](const Header& h) {
                                  return h.path == kernel_support_path;
                                })->text;
    for (const Header& header : printed) {
      if (header.path == kernel_support_path) continue;
      const std::vector<KernelProblem> found =
          header.kernels == nullptr
              ? prove_kernel_list(header.text, derivation.kernels, derivation.reference_kernels,
                                  model.reference_namespace)
              : prove_printed(support + header.text, *header.kernels, derivation.claims, derivation.rounding,
                              entry.proves_rounding_of);
      problems.insert(problems.end(), found.begin(), found.end());
    }
  }
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
    if (verified && problems.empty()) {
      for (const Header& header : headers(json_text)) {
        if (header.path == kernel_support_path && std::exchange(support_written, true)) continue;
        write(header.path, header.text);
      }
    }
  } catch (const std::exception& error) {
    std::cerr << "billiards-derive: " << error.what() << "\n";
    return exit_io;
  }
  return report(derivation, problems, written, std::cout, std::cerr) == 0 ? 0 : exit_claims_failed;
}

}  // namespace

int derive_main(int argc, const char* const* argv, const std::vector<ModelEntry>& models,
                const std::vector<Canary>& canaries) {
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
      "claim failed, a kernel is not proven or one of the prover's canaries (its own checks, asked first) "
      "answered wrongly (each is named on stderr; the audit is still written, the kernels are not), 2 on a "
      "usage error, 3 when an output cannot be written.\n"
      "Environment: BILLIARDS_PROOF_CACHE=DIR keeps Gappa's answers in DIR and takes them from there on "
      "later "
      "runs (the same Gappa version and script only); unset, every proof is run.");
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
  // The prover checked before it proves anything.
  const std::vector<CanaryOutcome> answers = ask_canaries(canaries);
  for (const CanaryOutcome& canary : answers) {
    if (!canary.as_expected())
      std::cerr << "PROVER CANARY FAILED " << canary.id << ": " << canary.statement << ": expected `"
                << canary.expected << "`, answered `" << canary.answered << "`\n";
  }
  int status = 0;
  bool support_written = false;
  for (const ModelEntry* entry : chosen) {
    const int model_status = run_model(*entry, fs::path(out), answers, support_written);
    if (model_status == exit_io) return exit_io;
    status = std::max(status, model_status);
  }
  if (billiards_support::standard_output_failed("billiards-derive")) return exit_io;
  return status;
}

}  // namespace billiards::derive
