// billiards-derive-mutant: billiards-derive with one mutation of the paper's kernels applied after the
// model is built, for the mutation suite. Usage: billiards-derive-mutant MUTATION [billiards-derive
// options]; `--list` prints the mutations, one "name kernel" line each.
#include "models/parkin2023/paper.hpp"
#include "mutations.hpp"
#include "run.hpp"

#include <iostream>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  using namespace billiards::derive;
  const std::string wanted = argc > 1 ? argv[1] : "";
  if (wanted == "--list") {
    for (const testing::Mutation& m : testing::paper_mutations())
      std::cout << m.name << " " << m.kernel << "\n";
    return 0;
  }
  for (const testing::Mutation& mutation : testing::paper_mutations()) {
    if (mutation.name != wanted) continue;
    const std::vector<ModelEntry> models = {{"parkin2023", [&mutation] {
                                               Derivation derivation = parkin2023::derive();
                                               testing::apply(mutation, derivation);
                                               return derivation;
                                             }}};
    std::vector<const char*> rest{argv[0]};
    for (int i = 2; i < argc; ++i) rest.push_back(argv[i]);
    return derive_main(static_cast<int>(rest.size()), rest.data(), models);
  }
  std::cerr << "billiards-derive-mutant: unknown mutation '" << wanted << "' (--list lists them)\n";
  return 2;
}
