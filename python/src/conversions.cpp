#include "conversions.hpp"

#include <cmath>
#include <sstream>

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
  if (space.is_discrete()) {
    const py::array array = py::array::ensure(value);
    require(array && array.size() == 1 && array.ndim() <= 1,
            "a Discrete(" + std::to_string(space.n()) + ") action is one integer index, got " +
                (array ? "an array of shape " + shape_text(array) : std::string("a non-number")),
            where);
    require(array.dtype().kind() == 'i' || array.dtype().kind() == 'u',
            "a Discrete action must be an integer, got dtype " +
                py::str(array.dtype()).cast<std::string>(),
            where);
    Action action(1);
    action[0] = static_cast<float>(array.attr("item")().cast<int64_t>());
    return action;
  }
  const FloatArray array = FloatArray::ensure(value);
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
  const FloatArray array = FloatArray::ensure(value);
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

}  // namespace tendril::python
