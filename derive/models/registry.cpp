// The registry of models: one line each. billiards-derive runs them in this order.
#include "model.hpp"
#include "models/parkin2023/paper.hpp"
#include "models/shot/shot.hpp"
#include "models/spinning/spinning.hpp"

namespace billiards::derive {

const std::vector<ModelEntry>& registered_models() {
  static const std::vector<ModelEntry> models = {
      {"parkin2023", [] { return parkin2023::derive(); }},
      {"spinning", [] { return spinning::derive(); }},
      {"shot", [] { return shot::derive(); }},
  };
  return models;
}

}  // namespace billiards::derive
