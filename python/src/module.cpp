// The extension module under the `tendril` Python package (python/tendril).
#include <pybind11/pybind11.h>

#include <string>

#include "bindings.hpp"
#include "tendril/core/error.hpp"
#include "tendril/core/numerics_mode.hpp"

PYBIND11_MODULE(_tendril, m) {
  m.doc() = "tendril's environments, vector environments, policies and trainer (C++).";
  // tendril::Error becomes tendril.Error, a ValueError carrying tendril's message.
  pybind11::register_exception<tendril::Error>(m, "Error", PyExc_ValueError);
  tendril::python::bind_env(m);
  tendril::python::bind_vec_env(m);
  tendril::python::bind_policy(m);
  tendril::python::bind_train(m);
  m.def("numerics", &tendril::numerics_description,
        "How this build's floating-point results reproduce: the build mode and the OpenBLAS "
        "kernels in use (docs/reproducibility.md).");
  // A portable build promises identical results only with its kernels pinned, which the
  // libraries read when they load: before Python starts.
  if (tendril::numerics_mode().portable && !tendril::numerics_mode().kernels_pinned) {
    const std::string message =
        "tendril was built in portable mode but its kernels are not "
        "pinned; results may differ across CPUs. Start Python with " +
        tendril::portable_kernel_variables();
    PyErr_WarnEx(PyExc_RuntimeWarning, message.c_str(), 1);
  }
}
