#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "tendril/core/config.hpp"
#include "tendril/core/env.hpp"
#include "tendril/core/scene.hpp"
#include "tendril/envs/vector/vec_step.hpp"
#include "tendril/render/image.hpp"

namespace tendril::python {

namespace py = pybind11;

// A float32 NumPy array of any shape and layout, converted to C order when needed.
using FloatArray = py::array_t<float, py::array::c_style | py::array::forcecast>;

// {"kind": "box", "low": float32[n], "high": float32[n]} or {"kind": "discrete", "n": n}.
py::dict space_to_dict(const Space& space);

// {name: value} of a step's named scalars.
py::dict info_to_dict(const Info& info);

// The scene as NumPy arrays (lab frame, metres): {"time", "rods": [{"role", "centreline"
// (nodes × 3), "radii"}], "spheres", "cylinders", "boxes", "planes", "lattices", "paths",
// "values"}.
py::dict scene_to_dict(const Scene& scene);

// Parameters given as JSON text (a YAML flow mapping) by the Python side; `what` names them in
// errors ("tendril.make('Pendulum-v1') params").
Config params_from_json(const std::string& json, const std::string& what);

// One action for `space`, from a NumPy array or Python number: a Box action of exactly the
// space's size (shape (n,) or, for n = 1, a scalar), a Discrete action as an integer index.
// Raises Error naming `who` and the shape found otherwise; values are checked by Env::step.
Action action_from_python(const Space& space, const py::handle& value, std::string_view who);

// (rows × cols) actions for `space` from a NumPy batch, into `out`. Raises Error naming `who`
// and the shape found unless it is (num_envs, size), or (num_envs,) for Discrete or size 1.
void batch_from_python(const Space& space, int num_envs, const py::handle& value,
                       std::string_view who, envs::BatchMatrix& out);

// A height × width × 3 uint8 array holding a copy of the image.
py::array_t<uint8_t> image_to_numpy(const render::Image& image);

// A NumPy view of `data` owned by `owner` (kept alive by the array), read-only.
py::array readonly_view(const float* data, std::vector<py::ssize_t> shape, py::handle owner);

// A float32 copy of `data`.
py::array float_copy(const float* data, std::vector<py::ssize_t> shape);

// A reset seed: None, or an integer (Python or NumPy) from 0 to 2^64 − `count` — a vector env
// resets env i with seed + i, which must not wrap around to 0. Raises Error naming `who` and the
// value otherwise (a float, a negative or too large number, text).
std::optional<uint64_t> seed_from_python(const py::handle& value, uint64_t count,
                                         std::string_view who);

// A count (environments, threads) as an integer in [1, 2^31 − 1]; Error naming `what` otherwise.
int count_from_python(const py::handle& value, std::string_view what, std::string_view who);

// Binary data saved from an environment's state with a checksum (CRC-32C), and the state back
// from such data: Error when the data is not such a state or was changed since.
py::bytes checksummed_state(const std::string& state);
std::string verified_state(const std::string& data, std::string_view who);

}  // namespace tendril::python
