// The extension module under the `tendril` Python package (python/tendril).
#include <pybind11/pybind11.h>

#include <exception>
#include <string>

#include "bindings.hpp"
#include "tendril/core/error.hpp"
#include "tendril/core/numerics_mode.hpp"
#ifdef TENDRIL_WITH_DYNAMICS
#include "tendril/dynamics/env_model_loader.hpp"
#include "tendril/dynamics/policy_heads.hpp"
#endif

PYBIND11_MODULE(_tendril, m) {
  m.doc() = "tendril's environments, vector environments, policies and trainer (C++).";
  // tendril::Error becomes tendril.Error, a ValueError carrying tendril's message. A message
  // may quote bytes from a damaged file that are not UTF-8: they appear as \xNN escapes (a
  // strict decoding would fail and leave the exception without its message).
  static pybind11::exception<tendril::Error> error(m, "Error", PyExc_ValueError);
  pybind11::register_exception_translator([](std::exception_ptr raised) {
    try {
      if (raised) std::rethrow_exception(raised);
    } catch (const tendril::Error& e) {
      const std::string text = e.what();
      PyObject* message = PyUnicode_DecodeUTF8(text.data(), static_cast<Py_ssize_t>(text.size()),
                                               "backslashreplace");
      PyErr_SetObject(error.ptr(), message);
      Py_XDECREF(message);
    }
  });
#ifdef TENDRIL_WITH_DYNAMICS
  // Environments around learned models open them from their `model` parameter, and policies
  // with learned-model heads are trained and loaded, as from the command line.
  tendril::dynamics::install_model_loader();
  tendril::dynamics::install_policy_heads();
#endif
  tendril::python::bind_env(m);
  tendril::python::bind_vec_env(m);
  tendril::python::bind_policy(m);
  tendril::python::bind_train(m);
  tendril::python::bind_render(m);
  tendril::python::bind_curves(m);
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
