// The derivation of the paper: every claim verified, one assumption, and perturbed definitions caught.
#include "audit/audit.hpp"
#include "models/parkin2023/paper.hpp"
#include "run.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>

using namespace billiards::derive;

namespace {

const Derivation& paper_derivation() {
  static const Derivation derivation = parkin2023::derive();
  return derivation;
}

const Claim* find_claim(const Derivation& derivation, const std::string& id) {
  for (const Claim& claim : derivation.claims) {
    if (claim.id == id) return &claim;
  }
  return nullptr;
}

// Substitutes numbers for the derivation's symbols, found by name (they are internal to it).
GiNaC::ex by_name(const GiNaC::ex& e, const std::map<std::string, GiNaC::numeric>& values) {
  GiNaC::exmap substitution;
  for (GiNaC::const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it) {
    if (GiNaC::is_a<GiNaC::symbol>(*it)) {
      const auto found = values.find(GiNaC::ex_to<GiNaC::symbol>(*it).get_name());
      if (found != values.end()) substitution[*it] = found->second;
    }
  }
  return e.subs(substitution);
}

bool contains(const std::vector<std::string>& ids, const std::string& id) {
  return std::find(ids.begin(), ids.end(), id) != ids.end();
}

}  // namespace

TEST_CASE("The paper's derivation checks out", "[derive][paper]") {
  const Derivation& derivation = paper_derivation();
  const Summary summary = summarize(derivation.claims);

  SECTION("every claim is verified except the one assumption") {
    for (const Claim& claim : derivation.claims) {
      INFO(claim.id);
      CHECK(claim.verdict != Verdict::failed);
    }
    CHECK(summary.failed == 0);
    CHECK(summary.assumption == 1);
    CHECK(summary.verified >= 20);
  }
  SECTION("the only assumption is that the tangential parts are unchanged") {
    for (const Claim& claim : derivation.claims) {
      if (claim.verdict == Verdict::assumption) {
        CHECK(claim.id == "assumption.tangential_velocity_unchanged");
        CHECK_FALSE(claim.note.empty());
      }
    }
  }
  SECTION("ids are unique, stable and descriptive, never ordinals") {
    std::set<std::string> seen;
    const std::regex descriptive("[a-z][a-z0-9_]*(\\.[a-z0-9_]+)+");
    for (const Claim& claim : derivation.claims) {
      INFO(claim.id);
      CHECK(seen.insert(claim.id).second);
      CHECK(std::regex_match(claim.id, descriptive));
      CHECK_FALSE(std::regex_search(claim.id, std::regex("\\.[0-9]+$")));
    }
  }
  SECTION("the claims the audit promises are all there") {
    for (const char* id : {"split.momentum.2d",
                           "split.momentum.3d",
                           "split.kinetic.2d",
                           "split.kinetic.3d",
                           "split.kinetic_cross_term.3d",
                           "assumption.tangential_velocity_unchanged",
                           "quadratic.coefficient_a",
                           "quadratic.coefficient_b",
                           "quadratic.coefficient_c",
                           "discriminant.paper_form",
                           "discriminant.expanded",
                           "discriminant.factored",
                           "discriminant.nonnegative",
                           "roots.quadratic_formula.relative_speed_nonnegative",
                           "roots.quadratic_formula.relative_speed_negative",
                           "roots.absolute_value_dropped.relative_speed_nonnegative",
                           "roots.absolute_value_dropped.relative_speed_negative",
                           "selection.minus_root_is_no_collision",
                           "selection.plus_root_reverses_relative_normal_velocity",
                           "result.x2_by_symmetry",
                           "result.x1_expanded_form",
                           "result.x1_simplified_form",
                           "result.independent_of_normal_sign",
                           "sanity.equal_masses_at_rest.x1",
                           "sanity.equal_masses_at_rest.x2",
                           "sanity.head_on.x1",
                           "sanity.head_on.x2",
                           "cushion.limit",
                           "cushion.reflection_is_sandwich.3d",
                           "conservation.momentum.2d",
                           "conservation.momentum.3d",
                           "conservation.kinetic_energy.2d",
                           "conservation.kinetic_energy.3d"}) {
      INFO(id);
      CHECK(find_claim(derivation, id) != nullptr);
    }
  }
  SECTION("every claim names what it rests on, and that comes before it") {
    std::set<std::string> earlier;
    for (const Premise& premise : derivation.premises) earlier.insert(premise.id);
    for (const Claim& claim : derivation.claims) {
      INFO(claim.id);
      for (const std::string& upstream : claim.depends_on) CHECK(earlier.count(upstream) == 1);
      earlier.insert(claim.id);
    }
  }
  SECTION("the selected root is the paper's result, in exact rationals") {
    // m1 = 3, m2 = 5, v1·n = 7/2, v2·n = −1: x1·n = v1·n + 2 m2/(m1 + m2) ((v2 − v1)·n) = −17/8 and
    // x2·n = v2·n − 2 m1/(m1 + m2) ((v2 − v1)·n) = 19/8, by hand.
    // The elastic kernel's claim holds the changes x1·n − v1·n and x2·n − v2·n as derived.
    const Claim* claim = find_claim(derivation, "kernel.elastic_normal_velocity_change");
    REQUIRE(claim != nullptr);
    const std::map<std::string, GiNaC::numeric> at{
        {"m1", 3}, {"m2", 5}, {"v1n", GiNaC::numeric(7, 2)}, {"v2n", -1}};
    const GiNaC::ex x1 = by_name(claim->derived_expression.op(0), at) + GiNaC::numeric(7, 2);
    CHECK(GiNaC::normal(x1 - GiNaC::numeric(-17, 8)).is_zero());
    const GiNaC::ex x2 = by_name(claim->derived_expression.op(1), at) - 1;
    CHECK(GiNaC::normal(x2 - GiNaC::numeric(19, 8)).is_zero());
  }
}

TEST_CASE("A perturbed definition fails the claims downstream of it", "[derive][perturbation]") {
  SECTION("K with the ½ dropped from m2's term: every printed formula downstream fails") {
    parkin2023::Definitions wrong;
    wrong.kinetic_coefficient_2 = 1;  // K(a, b) = ½ m1 a² + m2 b²
    const Derivation derivation = parkin2023::derive(wrong);
    // These state properties that hold for any K(a, b) = α m1 a² + β m2 b², so they must stay true:
    // the split (no cross terms), the reduction to normal components, and that the derived result
    // conserves the K it was derived from. (D ≥ 0 still holds too, but the sign claim also compares D
    // with the paper's m1²((v2 − v1)·n)², which it no longer is.)
    const std::set<std::string> true_of_any_such_K = {"split.kinetic.2d",
                                                      "split.kinetic.3d",
                                                      "along_n.kinetic_energy",
                                                      "along_n.kinetic_energy_in_normal_components",
                                                      "conservation.momentum.2d",
                                                      "conservation.momentum.3d",
                                                      "conservation.kinetic_energy.2d",
                                                      "conservation.kinetic_energy.3d"};
    const std::vector<std::string> downstream = downstream_of(derivation.claims, "definition.kinetic_energy");
    REQUIRE(downstream.size() >= 20);
    for (const Claim& claim : derivation.claims) {
      INFO(claim.id);
      if (!contains(downstream, claim.id)) {
        CHECK(claim.verdict != Verdict::failed);  // upstream of K or independent of it
      } else if (true_of_any_such_K.count(claim.id) != 0) {
        CHECK(claim.verdict == Verdict::verified);
      } else {
        CHECK(claim.verdict == Verdict::failed);
      }
    }
    CHECK(summarize(derivation.claims).failed >= 20);
  }
  SECTION("K with the ½ dropped from both terms: the coefficients and D fail, the roots cannot") {
    // K → 2K scales the energy equation K(v) = K(x) by 2: its roots, and so everything from the roots
    // on, are unchanged. What the paper prints for A, B, C and D is no longer what is derived.
    parkin2023::Definitions doubled;
    doubled.kinetic_coefficient_1 = 1;
    doubled.kinetic_coefficient_2 = 1;
    const Derivation derivation = parkin2023::derive(doubled);
    for (const char* id : {"quadratic.vector_form", "quadratic.in_normal_component",
                           "quadratic.coefficient_a", "quadratic.coefficient_b", "quadratic.coefficient_c",
                           "discriminant.paper_form", "discriminant.expanded", "discriminant.factored"}) {
      INFO(id);
      CHECK(find_claim(derivation, id)->verdict == Verdict::failed);
    }
    CHECK(find_claim(derivation, "result.x1_simplified_form")->verdict == Verdict::verified);
  }
  SECTION("the report names every failed claim with its residual, one line each") {
    parkin2023::Definitions wrong;
    wrong.kinetic_coefficient_2 = 1;
    const Derivation derivation = parkin2023::derive(wrong);
    std::ostringstream out, err;
    const int failed = report(derivation, {}, {"dir/AUDIT.md"}, out, err);
    CHECK(failed == summarize(derivation.claims).failed);
    CHECK(out.str().find("failed: " + std::to_string(failed)) != std::string::npos);
    CHECK(out.str().find("dir/AUDIT.md") != std::string::npos);
    const std::string errors = err.str();
    CHECK(std::count(errors.begin(), errors.end(), '\n') == failed);
    CHECK(errors.find("FAILED discriminant.factored: residual ") != std::string::npos);
    std::ostringstream clean_out, clean_err;
    CHECK(report(paper_derivation(), {}, {}, clean_out, clean_err) == 0);
    CHECK(clean_err.str().empty());
  }
  SECTION("P with m2 doubled: everything from momentum conservation on fails") {
    parkin2023::Definitions wrong;
    wrong.momentum_coefficient_2 = 2;
    const Derivation derivation = parkin2023::derive(wrong);
    for (const char* id : {"quadratic.x2_from_momentum", "quadratic.coefficient_a", "discriminant.factored",
                           "roots.quadratic_formula.relative_speed_nonnegative", "result.x1_simplified_form",
                           "result.x2_by_symmetry", "sanity.head_on.x1", "cushion.limit"}) {
      INFO(id);
      CHECK(find_claim(derivation, id)->verdict == Verdict::failed);
    }
  }
}

TEST_CASE("The audit", "[derive][audit]") {
  const Derivation& derivation = paper_derivation();

  SECTION("the JSON has its schema's fields, every one on every claim") {
    const nlohmann::json audit = nlohmann::json::parse(audit_json(derivation));
    CHECK(audit.at("schema") == 4);
    CHECK(audit.at("ginac") == ginac_version());
    REQUIRE(audit.at("claims").size() == derivation.claims.size());
    for (const auto& claim : audit.at("claims")) {
      for (const char* key : {"id", "paper", "statement", "method", "verdict", "section", "comparison",
                              "paper_tex", "paper_latex", "derived_latex", "residual", "failure",
                              "depends_on", "constraints", "cases", "note"}) {
        INFO(claim.at("id") << ": " << key);
        CHECK(claim.contains(key));
      }
      CHECK(claim.at("constraints").is_array());
      CHECK(claim.at("cases").is_array());
      const std::string verdict = claim.at("verdict");
      CHECK((verdict == "verified" || verdict == "failed" || verdict == "assumption"));
    }
    const Summary summary = summarize(derivation.claims);
    CHECK(audit.at("summary").at("verified") == summary.verified);
    CHECK(audit.at("summary").at("failed") == summary.failed);
    CHECK(audit.at("summary").at("assumption") == summary.assumption);
  }
  SECTION("the Markdown opens with the summary table and cites the paper and the scope") {
    const std::string markdown = audit_markdown(derivation);
    const auto summary_at = markdown.find("## Summary");
    REQUIRE(summary_at != std::string::npos);
    CHECK(summary_at < markdown.find("## Premises"));
    CHECK(markdown.find("S. T. Parkin, \"Billiard Ball Physics\", 2023") != std::string::npos);
    CHECK(markdown.find("frictionless, spinless") != std::string::npos);
    for (const Claim& claim : derivation.claims) {
      INFO(claim.id);
      CHECK(markdown.find("### " + claim.id + "\n") != std::string::npos);
    }
  }
  SECTION("a second run writes the same bytes") {
    const Derivation again = parkin2023::derive();
    CHECK(audit_markdown(again) == audit_markdown(derivation));
    CHECK(audit_json(again) == audit_json(derivation));
  }
}

TEST_CASE("A slip that GiNaC cannot compare fails its claims and the run goes on", "[derive][perturbation]") {
  // B² + 4AC for the discriminant: no perfect square, so √D stays a square root and reducing modulo
  // n·n = 1 meets a non-integer power, which GiNaC refuses with an exception.
  parkin2023::Definitions slip;
  slip.discriminant_ac_coefficient = 4;
  Derivation derivation;
  REQUIRE_NOTHROW(derivation = parkin2023::derive(slip));
  const Summary summary = summarize(derivation.claims);
  CHECK(summary.failed >= 8);
  // At least one comparison threw inside GiNaC and was turned into a failure with its reason.
  CHECK(std::any_of(derivation.claims.begin(), derivation.claims.end(), [](const Claim& c) {
    return c.failure.find("could not be carried out") != std::string::npos;
  }));
  CHECK(find_claim(derivation, "discriminant.factored")->verdict == Verdict::failed);
  CHECK(find_claim(derivation, "result.x1_simplified_form")->verdict == Verdict::failed);
  // Claims before the slip and claims that do not rest on it stand.
  CHECK(find_claim(derivation, "quadratic.coefficient_c")->verdict == Verdict::verified);
  CHECK(find_claim(derivation, "beyond.time_of_impact.stable_form")->verdict == Verdict::verified);
  // Every failed claim is named, and the audit can be written.
  std::ostringstream out, err;
  const std::vector<KernelProblem> problems = validate_kernels(derivation.kernels, derivation.claims);
  CHECK_FALSE(problems.empty());
  report(derivation, problems, {}, out, err);
  for (const Claim& claim : derivation.claims) {
    if (claim.verdict == Verdict::failed)
      CHECK(err.str().find("FAILED " + claim.id + ":") != std::string::npos);
  }
  CHECK_NOTHROW(audit_markdown(derivation));
  CHECK_NOTHROW(audit_json(derivation));
}

TEST_CASE("A slip runs billiards-derive to the end: the audit written, every failed claim named, exit 1",
          "[derive][perturbation]") {
  namespace fs = std::filesystem;
  parkin2023::Definitions half_dropped, plus_four_ac;
  half_dropped.kinetic_coefficient_2 = 1;        // K(a, b) = ½ m1 a² + m2 b²
  plus_four_ac.discriminant_ac_coefficient = 4;  // B² + 4AC
  for (const parkin2023::Definitions& slip : {half_dropped, plus_four_ac}) {
    const fs::path out = fs::temp_directory_path() / "billiards-slip";
    fs::remove_all(out);
    const std::vector<ModelEntry> models = {{"parkin2023", [slip] { return parkin2023::derive(slip); }}};
    const std::string folder = out.string();
    const char* argv[] = {"billiards-derive", "--out", folder.c_str()};
    std::ostringstream out_text, err_text;
    std::streambuf* const old_out = std::cout.rdbuf(out_text.rdbuf());
    std::streambuf* const old_err = std::cerr.rdbuf(err_text.rdbuf());
    const int status = derive_main(3, argv, models);
    std::cout.rdbuf(old_out);
    std::cerr.rdbuf(old_err);
    CHECK(status == exit_claims_failed);
    CHECK(fs::exists(out / "AUDIT.md"));
    CHECK(fs::exists(out / "audit.json"));
    CHECK_FALSE(fs::exists(out / "billiards" / "kernels.hpp"));
    const Derivation derivation = parkin2023::derive(slip);
    CHECK(summarize(derivation.claims).failed > 0);
    for (const Claim& claim : derivation.claims) {
      INFO(claim.id);
      if (claim.verdict == Verdict::failed)
        CHECK(err_text.str().find("FAILED " + claim.id + ":") != std::string::npos);
    }
    CHECK(err_text.str().find("KERNEL NOT PROVEN") != std::string::npos);
    fs::remove_all(out);
  }
}
