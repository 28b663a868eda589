// The registry of models: one line each. billiards-derive runs them in this order.
#include "derivation.hpp"
#include "model.hpp"

namespace billiards::derive {

const std::vector<ModelEntry>& registered_models() {
  static const std::vector<ModelEntry> models = {
      {"parkin2023", [] { return derive_paper(); }},
  };
  return models;
}

}  // namespace billiards::derive
