#include "conversions.hpp"

#include <climits>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>

#include "tendril/core/crc32c.hpp"
#include "tendril/core/error.hpp"

namespace tendril::python {

namespace {

py::array_t<float> copy_floats(const Eigen::VectorXf& values) {
  py::array_t<float> out(values.size());
  std::copy(values.data(), values.data() + values.size(), out.mutable_data());
  return out;
}

py::array_t<double> points_array(const Eigen::Matrix3Xd& points) {
  py::array_t<double> out({static_cast<py::ssize_t>(points.cols()), py::ssize_t{3}});
  auto view = out.mutable_unchecked<2>();
  for (Eigen::Index c = 0; c < points.cols(); ++c) {
    for (int r = 0; r < 3; ++r) view(c, r) = points(r, c);
  }
  return out;
}

py::array_t<double> vector3(const Eigen::Vector3d& v) {
  py::array_t<double> out(3);
  std::copy(v.data(), v.data() + 3, out.mutable_data());
  return out;
}

std::string shape_text(const py::array& array) {
  std::ostringstream text;
  text << "(";
  for (py::ssize_t d = 0; d < array.ndim(); ++d) {
    text << (d ? ", " : "") << array.shape(d);
  }
  text << (array.ndim() == 1 ? ",)" : ")");
  return text.str();
}

// repr(value), cut to a length fit for a message.
std::string short_repr(const py::handle& value) {
  std::string text = py::repr(value).cast<std::string>();
  if (text.size() > 60) text = text.substr(0, 57) + "...";
  return text;
}

// The array of numbers `value` holds, or Error: None, text, objects and complex numbers are not
// numbers an environment can take (NumPy would turn None into NaN and drop an imaginary part).
py::array number_array(const py::handle& value, const std::string& what, const std::string& who) {
  if (value.is_none()) throw Error(what + " must be numbers, got None", who);
  const py::array array = py::array::ensure(value);
  if (!array) throw Error(what + " must be numbers, got " + short_repr(value), who);
  const char kind = array.dtype().kind();
  if (kind == 'c') {
    throw Error(what + " must be real numbers, got complex " + short_repr(value), who);
  }
  if (kind != 'f' && kind != 'i' && kind != 'u' && kind != 'b') {
    throw Error(what + " must be numbers, got dtype " + py::str(array.dtype()).cast<std::string>() +
                    " (" + short_repr(value) + ")",
                who);
  }
  return array;
}

// The integer `value` holds (Python int, NumPy integer, anything with __index__), as a Python
// int; nothing for floats, text and booleans.
std::optional<py::int_> integer_of(const py::handle& value) {
  if (PyBool_Check(value.ptr())) return std::nullopt;
  PyObject* index = PyNumber_Index(value.ptr());
  if (index == nullptr) {
    PyErr_Clear();
    return std::nullopt;
  }
  return py::reinterpret_steal<py::int_>(index);
}

constexpr char kStateMagic[8] = {'t', 'n', 'd', 'l', 's', 't', 'a', '1'};

}  // namespace

py::dict space_to_dict(const Space& space) {
  py::dict out;
  if (space.is_discrete()) {
    out["kind"] = "discrete";
    out["n"] = space.n();
  } else {
    out["kind"] = "box";
    out["low"] = copy_floats(space.low());
    out["high"] = copy_floats(space.high());
  }
  return out;
}

py::dict info_to_dict(const Info& info) {
  py::dict out;
  for (const auto& [name, value] : info.entries()) out[py::str(name)] = value;
  return out;
}

py::array_t<uint8_t> image_to_numpy(const render::Image& image) {
  py::array_t<uint8_t> out({static_cast<py::ssize_t>(image.height),
                            static_cast<py::ssize_t>(image.width), py::ssize_t{3}});
  std::copy(image.rgb.begin(), image.rgb.end(), out.mutable_data());
  return out;
}

py::dict scene_to_dict(const Scene& scene) {
  py::dict out;
  out["time"] = scene.time;
  py::list rods, spheres, cylinders, boxes, planes, lattices, paths, values;
  for (const auto& rod : scene.rods) {
    py::array_t<double> radii(rod.radii.size());
    std::copy(rod.radii.data(), rod.radii.data() + rod.radii.size(), radii.mutable_data());
    rods.append(py::dict(py::arg("role") = rod.role,
                         py::arg("centreline") = points_array(rod.centreline),
                         py::arg("radii") = radii));
  }
  for (const auto& s : scene.spheres) {
    spheres.append(py::dict(py::arg("role") = s.role, py::arg("centre") = vector3(s.centre),
                            py::arg("radius") = s.radius));
  }
  for (const auto& c : scene.cylinders) {
    cylinders.append(py::dict(py::arg("role") = c.role, py::arg("start") = vector3(c.start),
                              py::arg("end") = vector3(c.end), py::arg("radius") = c.radius,
                              py::arg("capped") = c.capped));
  }
  for (const auto& b : scene.boxes) {
    const Eigen::Vector4d q(b.orientation.w(), b.orientation.x(), b.orientation.y(),
                            b.orientation.z());
    py::array_t<double> wxyz(4);
    std::copy(q.data(), q.data() + 4, wxyz.mutable_data());
    boxes.append(py::dict(py::arg("role") = b.role, py::arg("centre") = vector3(b.centre),
                          py::arg("half_extents") = vector3(b.half_extents),
                          py::arg("orientation_wxyz") = wxyz));
  }
  for (const auto& p : scene.planes) {
    planes.append(py::dict(py::arg("role") = p.role, py::arg("point") = vector3(p.point),
                           py::arg("normal") = vector3(p.normal)));
  }
  for (const auto& l : scene.lattices) {
    py::array_t<int> springs({static_cast<py::ssize_t>(l.springs.size()), py::ssize_t{2}});
    auto view = springs.mutable_unchecked<2>();
    for (std::size_t i = 0; i < l.springs.size(); ++i) {
      view(i, 0) = l.springs[i][0];
      view(i, 1) = l.springs[i][1];
    }
    lattices.append(py::dict(py::arg("role") = l.role, py::arg("nodes") = points_array(l.nodes),
                             py::arg("springs") = springs));
  }
  for (const auto& p : scene.paths) {
    paths.append(py::dict(py::arg("role") = p.role, py::arg("points") = points_array(p.points)));
  }
  py::dict named;
  for (const auto& [name, value] : scene.values) named[py::str(name)] = value;
  out["rods"] = rods;
  out["spheres"] = spheres;
  out["cylinders"] = cylinders;
  out["boxes"] = boxes;
  out["planes"] = planes;
  out["lattices"] = lattices;
  out["paths"] = paths;
  out["values"] = named;
  return out;
}

Config params_from_json(const std::string& json, const std::string& what) {
  return Config::parse(json, what);
}

Action action_from_python(const Space& space, const py::handle& value, std::string_view who) {
  const std::string where(who);
  const py::array numbers = number_array(value, "an action", where);
  if (space.is_discrete()) {
    const py::array& array = numbers;
    require(array.size() == 1 && array.ndim() <= 1,
            "a Discrete(" + std::to_string(space.n()) + ") action is one integer index, got " +
                "an array of shape " + shape_text(array),
            where);
    require(array.dtype().kind() == 'i' || array.dtype().kind() == 'u',
            "a Discrete action must be an integer, got dtype " +
                py::str(array.dtype()).cast<std::string>(),
            where);
    // A NumPy uint64 may exceed every int64 (the range itself is Env::step's to check).
    const py::int_ index = array.attr("item")();
    int overflow = 0;
    const long long chosen = PyLong_AsLongLongAndOverflow(index.ptr(), &overflow);
    if (overflow != 0) {
      throw Error("the Discrete(" + std::to_string(space.n()) + ") action " + short_repr(index) +
                      " lies outside [0, " + std::to_string(space.n()) + ")",
                  where);
    }
    Action action(1);
    action[0] = static_cast<float>(chosen);
    return action;
  }
  const FloatArray array = FloatArray::ensure(numbers);
  require(static_cast<bool>(array), "an action must be a number array", where);
  const auto size = static_cast<py::ssize_t>(space.size());
  const bool shaped =
      (array.ndim() == 1 && array.shape(0) == size) || (array.ndim() == 0 && size == 1);
  require(shaped,
          "expected an action of shape (" + std::to_string(size) + ",) for " + space.describe() +
              ", got shape " + shape_text(array),
          where);
  Action action(size);
  std::copy(array.data(), array.data() + size, action.data());
  return action;
}

void batch_from_python(const Space& space, int num_envs, const py::handle& value,
                       std::string_view who, envs::BatchMatrix& out) {
  const std::string where(who);
  const FloatArray array = FloatArray::ensure(number_array(value, "actions", where));
  require(static_cast<bool>(array), "actions must be a number array", where);
  const auto rows = static_cast<py::ssize_t>(num_envs);
  const auto cols = static_cast<py::ssize_t>(space.size());
  const bool shaped = (array.ndim() == 2 && array.shape(0) == rows && array.shape(1) == cols) ||
                      (array.ndim() == 1 && array.shape(0) == rows && cols == 1);
  require(shaped,
          "expected actions of shape (" + std::to_string(rows) + ", " + std::to_string(cols) +
              ") for " + std::to_string(rows) + " envs of " + space.describe() + ", got shape " +
              shape_text(array),
          where);
  out.resize(rows, cols);
  std::copy(array.data(), array.data() + rows * cols, out.data());
}

py::array readonly_view(const float* data, std::vector<py::ssize_t> shape, py::handle owner) {
  py::array view(py::dtype::of<float>(), std::move(shape), data, owner);
  py::detail::array_proxy(view.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return view;
}

py::array float_copy(const float* data, std::vector<py::ssize_t> shape) {
  return py::array(py::dtype::of<float>(), std::move(shape), data);
}

std::optional<uint64_t> seed_from_python(const py::handle& value, uint64_t count,
                                         std::string_view who) {
  if (value.is_none()) return std::nullopt;
  const uint64_t largest = std::numeric_limits<uint64_t>::max() - (count - 1);
  const std::string range =
      count > 1 ? "[0, 2**64 - " + std::to_string(count) + "] (env i is reset with seed + i)"
                : "[0, 2**64 - 1]";
  const std::optional<py::int_> integer = integer_of(value);
  if (!integer) {
    throw Error("the seed must be an integer in " + range + ", got " + short_repr(value),
                std::string(who));
  }
  const unsigned long long seed = PyLong_AsUnsignedLongLong(integer->ptr());
  if (PyErr_Occurred() || seed > largest) {  // negative, or beyond 64 bits, or wrapping
    PyErr_Clear();
    throw Error("the seed must be an integer in " + range + ", got " + short_repr(value),
                std::string(who));
  }
  return static_cast<uint64_t>(seed);
}

int count_from_python(const py::handle& value, std::string_view what, std::string_view who) {
  const std::optional<py::int_> integer = integer_of(value);
  int overflow = 0;
  const long long count = integer ? PyLong_AsLongLongAndOverflow(integer->ptr(), &overflow) : 0;
  if (!integer || overflow != 0 || count < 1 || count > INT_MAX) {
    throw Error(std::string(what) + " must be an integer in [1, " + std::to_string(INT_MAX) +
                    "], got " + short_repr(value),
                std::string(who));
  }
  return static_cast<int>(count);
}

py::bytes checksummed_state(const std::string& state) {
  std::string data(kStateMagic, sizeof kStateMagic);
  const uint32_t check = crc32c(state.data(), state.size());
  data.append(reinterpret_cast<const char*>(&check), sizeof check);
  data += state;
  return py::bytes(data);
}

std::string verified_state(const std::string& data, std::string_view who) {
  const std::size_t head = sizeof kStateMagic + sizeof(uint32_t);
  if (data.size() < head || std::memcmp(data.data(), kStateMagic, sizeof kStateMagic) != 0) {
    throw Error("not a state from save_state() (" + std::to_string(data.size()) + " bytes)",
                std::string(who));
  }
  uint32_t stored = 0;
  std::memcpy(&stored, data.data() + sizeof kStateMagic, sizeof stored);
  const uint32_t computed = crc32c(data.data() + head, data.size() - head);
  if (stored != computed) {
    throw Error(
        "the state's checksum does not match: its bytes changed after save_state() "
        "(CRC-32C " +
            checksum_text(computed) + ", saved " + checksum_text(stored) + ")",
        std::string(who));
  }
  return data.substr(head);
}

}  // namespace tendril::python
