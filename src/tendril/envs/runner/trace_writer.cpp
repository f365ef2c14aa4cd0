#include "tendril/envs/runner/trace_writer.hpp"

#include <cstdio>
#include <optional>

#include "tendril/core/error.hpp"
#include "tendril/core/scene.hpp"

namespace tendril::envs {

namespace {

std::string exact(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

}  // namespace

TraceWriter::TraceWriter(const std::filesystem::path& file) : file_(file) {
  require(!std::filesystem::exists(file), "exists already; choose another file", file.string());
  out_.open(file, std::ios::binary);
  require(out_.good(), "cannot write", file.string());
}

void TraceWriter::write_header(const StepView& step,
                               const std::vector<std::pair<std::string, double>>& scene) {
  std::string header = "episode,step,time,reward,terminated,truncated";
  for (Eigen::Index i = 0; i < step.observation.size(); ++i) {
    header += ",observation_" + std::to_string(i);
  }
  for (Eigen::Index i = 0; i < step.action.size(); ++i) header += ",action_" + std::to_string(i);
  for (Eigen::Index i = 0; i < step.observation.size(); ++i) {
    header += ",next_observation_" + std::to_string(i);
  }
  for (const auto& [name, value] : step.result.info.entries()) columns_.push_back(name);
  for (const auto& [name, value] : scene) {
    if (!step.result.info.has(name)) columns_.push_back(name);
  }
  for (const std::string& name : columns_) header += ',' + name;
  out_ << header << '\n';
  header_written_ = true;
}

void TraceWriter::on_step(const StepView& step) {
  Scene scene;
  step.env.describe_scene(scene);
  if (!header_written_) write_header(step, scene.values);
  const Step& result = step.result;
  std::string row = std::to_string(step.episode) + ',' + std::to_string(step.step) + ',' +
                    exact(scene.time) + ',' + exact(result.reward) + ',' +
                    (result.terminated ? "1" : "0") + ',' + (result.truncated ? "1" : "0");
  for (const float v : step.observation) row += ',' + exact(v);
  for (const float v : step.action) row += ',' + exact(v);
  for (const float v : result.observation) row += ',' + exact(v);
  for (const std::string& name : columns_) {
    std::optional<double> value = result.info.get(name);
    if (!value) {
      for (const auto& [key, scene_value] : scene.values) {
        if (key == name) value = scene_value;
      }
    }
    row += ',' + (value ? exact(*value) : std::string());
  }
  out_ << row << '\n';
  require(out_.good(), "writing failed (disk full?)", file_.string());
}

void TraceWriter::close() {
  out_.flush();
  require(out_.good(), "writing failed (disk full?)", file_.string());
  out_.close();
  require(!out_.fail(), "closing failed (disk full?)", file_.string());
}

}  // namespace tendril::envs
