// Pictures and videos (render/): a scene drawn into a NumPy image, videos through ffmpeg, and
// the policy export (rl/export) as the extension's functions.
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <string>

#include "bindings.hpp"
#include "conversions.hpp"
#include "tendril/core/episode_reader.hpp"
#include "tendril/core/error.hpp"
#include "tendril/render/episode_video.hpp"
#include "tendril/render/video_writer.hpp"
#include "tendril/rl/export/c_header.hpp"
#include "tendril/rl/export/policy_network.hpp"

namespace tendril::python {

namespace {

render::Image from_numpy(const py::handle& value, const std::string& who) {
  using Bytes = py::array_t<uint8_t, py::array::c_style | py::array::forcecast>;
  const Bytes array = Bytes::ensure(value);
  require(static_cast<bool>(array) && array.ndim() == 3 && array.shape(2) == 3,
          "a frame is a height x width x 3 uint8 array", who);
  render::Image image;
  image.width = static_cast<int>(array.shape(1));
  image.height = static_cast<int>(array.shape(0));
  image.rgb.assign(array.data(), array.data() + array.size());
  return image;
}

py::dict network_to_dict(const rl::PolicyNetwork& network) {
  py::dict out;
  out["kind"] = network.kind;
  out["observation_size"] = network.observation_size;
  out["action_size"] = network.action_size;
  out["action_choices"] = network.action_choices;
  out["output"] = rl::output_name(network.output);
  const auto floats = [](const std::vector<float>& values) {
    py::array_t<float> array(static_cast<py::ssize_t>(values.size()));
    std::copy(values.begin(), values.end(), array.mutable_data());
    return array;
  };
  out["mean"] = network.mean.empty() ? py::object(py::none()) : py::object(floats(network.mean));
  out["scale"] = network.mean.empty() ? py::object(py::none()) : py::object(floats(network.scale));
  out["clip"] = network.clip;
  out["low"] = floats(network.low);
  out["high"] = floats(network.high);
  py::list layers;
  for (const rl::PolicyNetwork::Layer& layer : network.layers) {
    py::array_t<float> weight(
        {static_cast<py::ssize_t>(layer.outputs), static_cast<py::ssize_t>(layer.inputs)});
    std::copy(layer.weight.begin(), layer.weight.end(), weight.mutable_data());
    layers.append(py::dict(py::arg("weight") = weight, py::arg("bias") = floats(layer.bias),
                           py::arg("activation") = rl::activation_name(layer.activation)));
  }
  out["layers"] = layers;
  return out;
}

std::filesystem::path policy_file(const std::filesystem::path& path, bool best) {
  if (!std::filesystem::is_directory(path)) return path;
  return path / (best ? "best_model.policy" : "model.policy");
}

}  // namespace

void bind_render(py::module_& m) {
  py::class_<render::VideoWriter>(m, "VideoWriter",
                                  "A video written frame by frame through ffmpeg (.mp4, .webm, "
                                  ".gif); the file appears when finish() succeeds.")
      .def(py::init<const std::filesystem::path&, int, int, double, std::string>(), py::arg("path"),
           py::arg("width"), py::arg("height"), py::arg("fps"), py::arg("ffmpeg") = "ffmpeg")
      .def(
          "write",
          [](render::VideoWriter& self, const py::handle& frame) {
            const render::Image image = from_numpy(frame, "VideoWriter.write");
            py::gil_scoped_release release;
            self.write(image);
          },
          py::arg("frame"))
      .def("finish", &render::VideoWriter::finish)
      .def_property_readonly("frames", &render::VideoWriter::frames);

  m.def(
      "episode_video",
      [](const std::filesystem::path& episode_file, const std::filesystem::path& out, int width,
         int height, double fps, double max_fps, double speed, int supersample, bool trails) {
        render::VideoOptions options;
        options.raster.width = width;
        options.raster.height = height;
        options.raster.supersample = supersample;
        options.fps = fps;
        options.max_fps = max_fps;
        options.speed = speed;
        options.trails = trails;
        py::gil_scoped_release release;
        return render::write_episode_video(read_episode(episode_file), out, options);
      },
      py::arg("episode"), py::arg("out"), py::arg("width") = 960, py::arg("height") = 540,
      py::arg("fps") = 0.0, py::arg("max_fps") = 30.0, py::arg("speed") = 0.0,
      py::arg("supersample") = 2, py::arg("trails") = true,
      "Writes a video of a recorded episode (.tep) with ffmpeg; returns its frame count.");

  m.def(
      "policy_network",
      [](const std::filesystem::path& path, bool best) {
        return network_to_dict(rl::policy_network(*rl::load_policy(policy_file(path, best))));
      },
      py::arg("path"), py::arg("best") = false,
      "A policy file's deterministic action as layers (rl::PolicyNetwork), for exporters.");
  m.def(
      "export_c_header",
      [](const std::filesystem::path& path, const std::filesystem::path& out,
         const std::string& name, bool best) {
        const std::filesystem::path file = policy_file(path, best);
        rl::write_c_header(*rl::load_policy(file), out, name, "from " + file.string());
      },
      py::arg("path"), py::arg("out"), py::arg("name") = "policy", py::arg("best") = false,
      "Writes a policy as a dependency-free C header (rl::write_c_header).");
}

}  // namespace tendril::python
