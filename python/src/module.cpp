// The extension module under the `tendril` Python package (python/tendril).
#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "tendril/core/error.hpp"

PYBIND11_MODULE(_tendril, m) {
  m.doc() = "tendril's environments, vector environments, policies and trainer (C++).";
  // tendril::Error becomes tendril.Error, a ValueError carrying tendril's message.
  pybind11::register_exception<tendril::Error>(m, "Error", PyExc_ValueError);
  tendril::python::bind_env(m);
  tendril::python::bind_vec_env(m);
  tendril::python::bind_policy(m);
  tendril::python::bind_train(m);
  tendril::python::bind_render(m);
}
