#pragma once

#include <pybind11/pybind11.h>

namespace tendril::python {

// The parts of the extension module `tendril._tendril`, each in its own file.
void bind_env(pybind11::module_& m);
void bind_vec_env(pybind11::module_& m);
void bind_policy(pybind11::module_& m);
void bind_train(pybind11::module_& m);
void bind_render(pybind11::module_& m);
void bind_curves(pybind11::module_& m);

}  // namespace tendril::python
