// billiards-derive for the example model alone. In the billiards tree a model is added to
// derive/models/registry.cpp instead: {"rolling", [] { return rolling::derive(); }}.
#include "rolling.hpp"
#include "run.hpp"

int main(int argc, char** argv) {
  return billiards::derive::derive_main(argc, argv, {{"rolling", [] { return rolling::derive(); }}});
}
