// The generic suite: what must hold of every registered model, and a tiny test-only model that shows a
// model can be registered and run through the whole pipeline without touching the generic layers.
#include "audit/audit.hpp"
#include "emit/emitter.hpp"
#include "emit/validate.hpp"
#include "model.hpp"
#include "run.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace billiards::derive;
using GiNaC::ex;

namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The tiny model: (a + b)² expanded, and a kernel that computes it as a square of the sum.
Derivation tiny_model(bool drifted) {
  const GiNaC::realsymbol a("a"), b("b");
  Derivation derivation;
  derivation.model.name = "tiny";
  derivation.model.title = "A tiny model";
  derivation.model.citation = "a test-only model";
  derivation.model.scope = "one identity";
  derivation.model.markdown_path = "tiny/AUDIT.md";
  derivation.model.json_path = "tiny/audit.json";
  derivation.model.kernels_path = "tiny/kernels.hpp";
  derivation.model.kernels_namespace = "tiny::kernels";
  Recorder record(derivation);
  record.premise({"definition.square_of_sum", "s(a, b) = (a + b)².", GiNaC::pow(a + b, 2)});
  record.section("expansion", "Expanding", "The square of a sum, expanded.");
  record.add({.id = "expansion.square_of_sum",
              .paper = "the binomial formula",
              .statement = "(a + b)² = a² + 2ab + b².",
              .method = "expand(); identity",
              .comparison = Comparison::identity,
              .paper_expression = a * a + 2 * a * b + b * b,
              .derived_expression = GiNaC::pow(a + b, 2).expand(),
              .constraints = {},
              .depends_on = {"definition.square_of_sum"}});
  const GiNaC::symbol sum("sum");
  derivation.kernels.push_back({.name = "square_of_sum",
                                .brief = "(a + b)², computed as the square of the sum.",
                                .parameters = {a, b},
                                .steps = {{sum, a + b}},
                                .outputs = {drifted ? ex(sum * sum + 1) : ex(sum * sum)},
                                .equals = "expansion.square_of_sum",
                                .rounding_cases = {{1 <= a, a <= 2, 1 <= b, b <= 2}}});
  return derivation;
}

int run(const std::vector<ModelEntry>& models, const std::vector<std::string>& arguments) {
  std::vector<const char*> argv{"billiards-derive"};
  for (const std::string& argument : arguments) argv.push_back(argument.c_str());
  return derive_main(static_cast<int>(argv.size()), argv.data(), models);
}

}  // namespace

TEST_CASE("Every registered model", "[derive][models]") {
  REQUIRE_FALSE(registered_models().empty());
  for (const ModelEntry& entry : registered_models()) {
    INFO(entry.name);
    const Derivation derivation = entry.derive();
    SECTION("names itself and its outputs") {
      CHECK(derivation.model.name == entry.name);
      CHECK_FALSE(derivation.model.citation.empty());
      CHECK_FALSE(derivation.model.markdown_path.empty());
      CHECK_FALSE(derivation.model.json_path.empty());
    }
    SECTION("has unique, descriptive ids, each resting only on what comes before it") {
      std::set<std::string> earlier;
      const std::regex descriptive("[a-z][a-z0-9_]*(\\.[a-z0-9_]+)+");
      for (const Premise& premise : derivation.premises) CHECK(earlier.insert(premise.id).second);
      for (const Claim& claim : derivation.claims) {
        INFO(claim.id);
        CHECK(std::regex_match(claim.id, descriptive));
        for (const std::string& upstream : claim.depends_on) CHECK(earlier.count(upstream) == 1);
        CHECK(earlier.insert(claim.id).second);
      }
    }
    SECTION("fails no claim, and every kernel is proven") {
      for (const Claim& claim : derivation.claims) {
        INFO(claim.id);
        CHECK(claim.verdict != Verdict::failed);
      }
      for (const KernelProblem& problem : validate_kernels(derivation.kernels, derivation.claims)) {
        FAIL_CHECK(problem.kernel + " (" + problem.claim + "): " + problem.reason);
      }
      for (const KernelProblem& problem : validate_kernels(derivation.reference_kernels, derivation.claims)) {
        FAIL_CHECK(problem.kernel + " (" + problem.claim + "): " + problem.reason);
      }
    }
    SECTION("writes the same bytes on a second run") {
      const Derivation again = entry.derive();
      CHECK(audit_markdown(again) == audit_markdown(derivation));
      const std::string json = audit_json(derivation);
      CHECK(audit_json(again) == json);
      CHECK(kernels_header(again, json) == kernels_header(derivation, json));
      CHECK(reference_kernels_header(again, json) == reference_kernels_header(derivation, json));
    }
  }
}

TEST_CASE("Every claim id cited in generated/, runtime/, the README and the guides exists and is verified",
          "[derive][models]") {
  // Verified, or the one kind of claim that is never checked: a stated assumption.
  std::set<std::string> ids, first_segments;
  for (const ModelEntry& entry : registered_models()) {
    for (const Claim& claim : entry.derive().claims) {
      if (claim.verdict != Verdict::failed) ids.insert(claim.id);
      first_segments.insert(claim.id.substr(0, claim.id.find('.')));
    }
  }
  // A citation: a dotted id whose first part names a section of some model, with `prefix.*` for every
  // claim under a prefix and `a.{b,c}` for a.b and a.c.
  const std::regex citation("\\b([a-z][a-z0-9_]*)((\\.([a-z0-9_]*\\{[a-z0-9_,]+\\}|[a-z0-9_]+|\\*))+)");
  const fs::path source(BILLIARDS_SOURCE_DIR);
  std::vector<fs::path> files{source / "README.md"};
  for (const auto& file : fs::directory_iterator(source / "docs")) {
    if (file.path().extension() == ".md") files.push_back(file.path());
  }
  for (const fs::path& folder : {source / "generated", source / "runtime" / "include"}) {
    for (const auto& file : fs::recursive_directory_iterator(folder)) {
      if (file.is_regular_file()) files.push_back(file.path());
    }
  }
  // Arguments the checked calls name in their errors that share a section's name, and their members in
  // code: not claims.
  const std::set<std::string> argument_names = {"cushion.normal", "cushion.height", "cushion.restitution",
                                                "cushion.friction"};
  int cited = 0;
  for (const fs::path& file : files) {
    const std::string text = read(file);
    for (auto it = std::sregex_iterator(text.begin(), text.end(), citation); it != std::sregex_iterator();
         ++it) {
      const std::string first = (*it)[1];
      if (!first_segments.count(first)) continue;
      std::string rest = (*it)[2];
      if (std::regex_search(rest, std::regex("\\.(hpp|cpp|md|json|svg)$"))) continue;
      // Expand one {a,b} group (enough for the citations in use), then match a trailing .* as a prefix.
      std::vector<std::string> candidates;
      const std::smatch::value_type whole = (*it)[0];
      const std::string id = whole.str();
      const auto open = id.find('{');
      if (open != std::string::npos) {
        const auto close = id.find('}', open);
        std::stringstream options(id.substr(open + 1, close - open - 1));
        for (std::string option; std::getline(options, option, ',');) {
          candidates.push_back(id.substr(0, open) + option + id.substr(close + 1));
        }
      } else {
        candidates.push_back(id);
      }
      for (const std::string& candidate : candidates) {
        if (std::any_of(argument_names.begin(), argument_names.end(), [&](const std::string& name) {
              return candidate == name || candidate.rfind(name + ".", 0) == 0;
            }))
          continue;
        INFO(file.string() + " cites " + candidate);
        ++cited;
        if (candidate.size() > 2 && candidate.substr(candidate.size() - 2) == ".*") {
          const std::string prefix = candidate.substr(0, candidate.size() - 1);
          CHECK(std::any_of(ids.begin(), ids.end(),
                            [&](const std::string& known) { return known.rfind(prefix, 0) == 0; }));
        } else {
          CHECK(ids.count(candidate) == 1);
        }
      }
    }
  }
  CHECK(cited > 50);
}

TEST_CASE("A model is registered without touching the generic layers", "[derive][models]") {
  const fs::path out = fs::temp_directory_path() / "billiards-tiny-model";
  fs::remove_all(out);
  SECTION("a proven kernel is printed, with the audit, where the model says") {
    const std::vector<ModelEntry> models = {{"tiny", [] { return tiny_model(false); }}};
    REQUIRE(run(models, {"--out", out.string()}) == 0);
    const std::string header = read(out / "tiny" / "kernels.hpp");
    CHECK(header.find("namespace tiny::kernels {") != std::string::npos);
    CHECK(header.find("square_of_sum(Scalar a, Scalar b) noexcept") != std::string::npos);
    CHECK(header.find("`expansion.square_of_sum`") != std::string::npos);
    const std::string audit = read(out / "tiny" / "AUDIT.md");
    CHECK(audit.find("# Derivation audit: \"A tiny model\"") != std::string::npos);
    CHECK(audit.find("| `square_of_sum` | [`expansion.square_of_sum`]") != std::string::npos);
    CHECK(read(out / "tiny" / "audit.json").find("\"model\": \"tiny\"") != std::string::npos);
  }
  SECTION("a kernel that drifts from its claim is not printed and the run fails") {
    const std::vector<ModelEntry> models = {{"tiny", [] { return tiny_model(true); }}};
    CHECK(run(models, {"--out", out.string()}) == exit_claims_failed);
    CHECK(fs::exists(out / "tiny" / "AUDIT.md"));
    CHECK_FALSE(fs::exists(out / "tiny" / "kernels.hpp"));
  }
  SECTION("--model picks one model, and an unknown one is a usage error") {
    const std::vector<ModelEntry> models = {{"tiny", [] { return tiny_model(false); }},
                                            {"broken", [] { return tiny_model(true); }}};
    CHECK(run(models, {"--out", out.string(), "--model", "tiny"}) == 0);
    CHECK(run(models, {"--out", out.string()}) == exit_claims_failed);
    CHECK(run(models, {"--out", out.string(), "--model", "nonesuch"}) == exit_usage);
  }
  SECTION("a model whose derivation throws fails the run, naming it, without a crash") {
    const std::vector<ModelEntry> models = {
        {"throws", []() -> Derivation { throw std::runtime_error("a step could not be carried out"); }}};
    CHECK(run(models, {"--out", out.string()}) == exit_claims_failed);
  }
  fs::remove_all(out);
}
