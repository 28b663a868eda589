#include "emit/kernel.hpp"

#include <algorithm>

namespace billiards::derive {

std::vector<std::string> cited_claims(const Kernel& kernel) {
  std::vector<std::string> ids;
  const auto cite = [&](const std::string& id) {
    if (!id.empty() && std::find(ids.begin(), ids.end(), id) == ids.end()) ids.push_back(id);
  };
  cite(kernel.equals);
  for (const std::string& id : kernel.claims) cite(id);
  for (const KernelStep& step : kernel.steps) {
    for (const Guard& guard : step.guards) cite(guard.claim);
  }
  if (kernel.fast_path) cite(kernel.fast_path->claim);
  return ids;
}

}  // namespace billiards::derive
