// billiards-derive-mutant: billiards-derive with one mutation of a model's kernels applied after the
// model is built, for the mutation suite. Usage: billiards-derive-mutant MUTATION [billiards-derive
// options]; `--list` prints the mutations, one "name kernel" line each.
#include "models/parkin2023/paper.hpp"
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
    const std::vector<testing::Mutation>& mutations;
  };
  const std::vector<Suite> suites = {
      {"parkin2023", [] { return parkin2023::derive(); }, testing::paper_mutations()},
      {"spinning", [] { return spinning::derive(); }, testing::spin_mutations()}};
  const std::string wanted = argc > 1 ? argv[1] : "";
  if (wanted == "--list") {
    for (const Suite& suite : suites) {
      for (const testing::Mutation& m : suite.mutations) std::cout << m.name << " " << m.kernel << "\n";
    }
    return 0;
  }
  for (const Suite& suite : suites) {
    for (const testing::Mutation& mutation : suite.mutations) {
      if (mutation.name != wanted) continue;
      const std::vector<ModelEntry> models = {{suite.model, [&suite, &mutation] {
                                                 Derivation derivation = suite.derive();
                                                 testing::apply(mutation, derivation);
                                                 return derivation;
                                               }}};
      std::vector<const char*> rest{argv[0]};
      for (int i = 2; i < argc; ++i) rest.push_back(argv[i]);
      return derive_main(static_cast<int>(rest.size()), rest.data(), models);
    }
  }
  std::cerr << "billiards-derive-mutant: unknown mutation '" << wanted << "' (--list lists them)\n";
  return 2;
}
