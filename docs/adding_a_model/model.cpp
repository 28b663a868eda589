// The model as a pipeline: what the audit says of it, where its outputs go, and its steps in order.
#include "rolling.hpp"

namespace rolling {

billiards::derive::Derivation derive() {
  billiards::derive::Derivation derivation;
  billiards::derive::ModelInfo& model = derivation.model;
  model.name = "rolling";
  model.title = "A ball rolling to rest";
  model.citation = "a ball rolling to rest on the cloth, from the rolling resistance";
  model.scope = "a ball rolling without slipping, slowed by rolling resistance alone";
  model.markdown_path = "rolling/AUDIT.md";
  model.json_path = "rolling/audit.json";
  model.kernels_path = "rolling/rolling_kernels.hpp";
  model.kernels_namespace = "rolling::kernels";
  billiards::derive::record_steps(derivation, [&](billiards::derive::Recorder& record) {
    record_premises(record);
    const Stopping stopping = the_stopping(record);
    derivation.kernels = rolling_kernels(stopping);
  });
  return derivation;
}

}  // namespace rolling
