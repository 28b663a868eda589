// What the bindings share: the arrays the pure-Python layer hands over (C-contiguous, of the dtype it
// chose, already broadcast), their shapes checked again here, and errors raised as Python exceptions
// that name the argument and, in a batch, the case.
#pragma once

#include <billiards/checked.hpp>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace billiards::python {

namespace py = pybind11;

/// A C-contiguous array of `Scalar` (the Python layer converts nothing: it hands over arrays of the
/// dtype the call runs in).
template <typename Scalar>
using Array = py::array_t<Scalar, py::array::c_style>;

/// The array's data, after checking that it holds `rows` rows of `columns` values each (`columns` 0:
/// a flat array of `rows` values).
template <typename Scalar>
[[nodiscard]] const Scalar* rows_of(const Array<Scalar>& a, const char* name, py::ssize_t rows,
                                    py::ssize_t columns = 0) {
  const bool flat = columns == 0;
  const bool fits = flat ? (a.ndim() == 1 && a.shape(0) == rows)
                         : (a.ndim() == 2 && a.shape(0) == rows && a.shape(1) == columns);
  if (!fits) {
    std::string shape = "(";
    for (py::ssize_t k = 0; k < a.ndim(); ++k) shape += (k ? ", " : "") + std::to_string(a.shape(k));
    throw py::value_error(std::string(name) + " has shape " + shape + "), expected (" + std::to_string(rows) +
                          (flat ? ",)" : ", " + std::to_string(columns) + ")"));
  }
  return a.data();
}

/// A new array of `rows` rows of `columns` values (`columns` 0: flat).
template <typename Scalar>
[[nodiscard]] Array<Scalar> new_rows(py::ssize_t rows, py::ssize_t columns = 0) {
  if (columns == 0) return Array<Scalar>(std::vector<py::ssize_t>{rows});
  return Array<Scalar>(std::vector<py::ssize_t>{rows, columns});
}

/// The first case of a batch whose arguments a checked call rejected, kept while the loop runs without
/// the GIL and raised as ValueError once it is held again.
class Rejection {
 public:
  /// `function` as Python knows it; `renamed` maps the C++ call's argument names ("ball.mass") to the
  /// Python call's ("mass").
  Rejection(std::string function, bool batch, std::map<std::string, std::string> renamed = {})
      : function_(std::move(function)), batch_(batch), renamed_(std::move(renamed)) {}

  /// Records the rejection of case `index` (the first one only).
  void record(std::size_t index, const billiards::invalid_argument& error) {
    if (message_) return;
    const auto name = renamed_.find(error.argument());
    const std::string argument = name == renamed_.end() ? error.argument() : name->second;
    message_ = function_ + ": " + argument + " is " + error.value() + ", expected " + error.expected() +
               (batch_ ? " (at flat index " + std::to_string(index) + " of the broadcast arguments)" : "");
  }
  /// Whether a case was rejected: the loop stops there.
  [[nodiscard]] bool any() const noexcept { return message_.has_value(); }
  /// Raises the recorded rejection as ValueError (the GIL held).
  void raise_if_any() const {
    if (message_) throw py::value_error(*message_);
  }

 private:
  std::string function_;
  bool batch_;
  std::map<std::string, std::string> renamed_;
  std::optional<std::string> message_;
};

void bind_runtime(py::module_& m);
void bind_engines(py::module_& m);
void bind_batch(py::module_& m);
void bind_files(py::module_& m);
void bind_table_and_gas(py::module_& m);
void bind_games(py::module_& m);

}  // namespace billiards::python
