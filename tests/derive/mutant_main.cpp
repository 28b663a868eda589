// billiards-derive-mutant: billiards-derive with one mutation of a model's kernels applied after the
// model is built, for the mutation suite. Usage: billiards-derive-mutant MUTATION [billiards-derive
// options]; `--list` prints the mutations, one "name culprit" line each ("name culprit harmless" for
// one that must pass). Beside the models' mutations: each prover canary told to expect a wrong answer.
#include "models/parkin2023/paper.hpp"
#include "models/shot/shot.hpp"
#include "models/spinning/spinning.hpp"
#include "mutations.hpp"
#include "run.hpp"

#include <functional>
#include <iostream>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  using namespace billiards::derive;
  struct Suite {
    std::string model;
    std::function<Derivation()> derive;
    std::vector<testing::Mutation> mutations;
  };
  const auto both = [](std::vector<testing::Mutation> first, const std::vector<testing::Mutation>& then) {
    first.insert(first.end(), then.begin(), then.end());
    return first;
  };
  const std::vector<Suite> suites = {{"parkin2023", [] { return parkin2023::derive(); },
                                      both(testing::paper_mutations(), testing::paper_class_mutations())},
                                     {"spinning", [] { return spinning::derive(); },
                                      both(testing::spin_mutations(), testing::spin_class_mutations())},
                                     {"shot", [] { return shot::derive(); }, testing::shot_mutations()}};
  const std::string wanted = argc > 1 ? argv[1] : "";
  // The canaries, each told to expect another answer than the sound one: the run must stop, naming it.
  const auto canary_mutation = [](const Canary& canary) {
    std::string name = "canary_expects_otherwise_" + canary.id;
    for (char& c : name) c = c == '.' ? '_' : c;
    return name;
  };
  if (wanted == "--list") {
    for (const Suite& suite : suites) {
      for (const testing::Mutation& m : suite.mutations)
        std::cout << m.name << " " << m.kernel << (m.harmless ? " harmless" : "") << "\n";
    }
    for (const Canary& canary : prover_canaries()) std::cout << canary_mutation(canary) << " " << canary.id << "\n";
    return 0;
  }
  for (const Canary& canary : prover_canaries()) {
    if (canary_mutation(canary) != wanted) continue;
    std::vector<Canary> canaries = prover_canaries();
    for (Canary& c : canaries) {
      if (c.id == canary.id) c.expected = "not " + c.expected;
    }
    std::vector<const char*> rest{argv[0]};
    for (int i = 2; i < argc; ++i) rest.push_back(argv[i]);
    return derive_main(static_cast<int>(rest.size()), rest.data(), {{"parkin2023", [] { return parkin2023::derive(); }}},
                       canaries);
  }
  for (const Suite& suite : suites) {
    for (const testing::Mutation& mutation : suite.mutations) {
      if (mutation.name != wanted) continue;
      std::vector<ModelEntry> models = {{suite.model, [&suite, &mutation] {
                                           Derivation derivation = suite.derive();
                                           testing::apply(mutation, derivation);
                                           return derivation;
                                         }}};
      // Gappa proves the rounding of the culprit alone: the suite asks that the culprit be named, and a
      // rounding proof names only its own kernel, so the other kernels' proofs cannot bear on it.
      models.front().proves_rounding_of = [&mutation](const std::string& name) { return name == mutation.kernel; };
      if (mutation.edit_printed) {
        models.front().edit_printed = [&mutation](const std::string& path, const std::string& text) {
          return path == mutation.header ? mutation.edit_printed(text) : text;
        };
      }
      std::vector<const char*> rest{argv[0]};
      for (int i = 2; i < argc; ++i) rest.push_back(argv[i]);
      return derive_main(static_cast<int>(rest.size()), rest.data(), models);
    }
  }
  std::cerr << "billiards-derive-mutant: unknown mutation '" << wanted << "' (--list lists them)\n";
  return 2;
}
