// billiards-derive: the command line over the registered models; the pipeline is in run.cpp, the models
// in models/.
#include "model.hpp"
#include "run.hpp"

int main(int argc, char** argv) {
  return billiards::derive::derive_main(argc, argv, billiards::derive::registered_models());
}
