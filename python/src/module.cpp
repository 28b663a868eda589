// billiards._billiards: the compiled half of the Python package (the runtime's calls over arrays, the
// engines, the batch, the file formats). Users import billiards, whose pure-Python layer documents and checks
// every argument before it reaches this module.
#include "arrays.hpp"

#include <billiards/version.hpp>

PYBIND11_MODULE(_billiards, m) {
  m.doc() = "The compiled half of the billiards package; use the billiards module.";
  m.attr("__version__") = BILLIARDS_VERSION;
  billiards::python::bind_runtime(m);
  billiards::python::bind_engines(m);
  billiards::python::bind_batch(m);
  billiards::python::bind_files(m);
  billiards::python::bind_table_and_gas(m);
  billiards::python::bind_games(m);
}
