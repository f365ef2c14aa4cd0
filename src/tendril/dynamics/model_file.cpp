#include "tendril/dynamics/model_file.hpp"

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "tendril/core/atomic_file.hpp"
#include "tendril/core/error.hpp"
#include "tendril/dynamics/model.hpp"
#include "tendril/dynamics/model_file_format.hpp"

namespace tendril::dynamics {

namespace {

std::vector<std::pair<std::string, torch::Tensor>> named_parameters(const Model& model) {
  std::vector<std::pair<std::string, torch::Tensor>> result;
  for (const auto& item : const_cast<Model&>(model).network().named_parameters()) {
    result.emplace_back(item.key(), item.value());
  }
  return result;
}

std::string list(const std::vector<std::string>& names) {
  std::string out = "[";
  for (std::size_t i = 0; i < names.size(); ++i) out += (i ? ", " : "") + names[i];
  return out + "]";
}

}  // namespace

std::filesystem::path model_file_path(const std::filesystem::path& file_or_run) {
  return std::filesystem::is_directory(file_or_run) ? file_or_run / kModelFileName : file_or_run;
}

void save_model(const Model& model, const std::filesystem::path& file, bool replace) {
  require(replace || !std::filesystem::exists(file), "exists; nothing is overwritten",
          file.string());
  ModelFileContents contents{model.description(), {}};
  for (const auto& [name, tensor] : named_parameters(model)) {
    const torch::Tensor values = tensor.detach().to(torch::kFloat).contiguous();
    const float* data = values.data_ptr<float>();
    contents.parameters.push_back(
        {name, values.sizes().vec(), std::vector<float>(data, data + values.numel())});
  }
  write_file_atomically(file, encode_model_file(contents), "model file");
}

std::unique_ptr<Model> load_model(const std::filesystem::path& file_or_run) {
  const std::filesystem::path path = model_file_path(file_or_run);
  const std::string file = path.string();
  std::ifstream in(path, std::ios::binary);
  require(in.good() && std::filesystem::is_regular_file(path), "no model file", file);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const ModelFileContents contents = decode_model_file(bytes, file);

  auto model = std::make_unique<Model>(contents.description, 0);
  const auto parameters = named_parameters(*model);
  std::vector<std::string> expected, found;
  for (const auto& [name, tensor] : parameters) expected.push_back(name);
  for (const StoredParameter& p : contents.parameters) found.push_back(p.name);
  require(
      expected == found,
      "the file's parameters " + list(found) + " do not match the architecture's " + list(expected),
      file);
  torch::NoGradGuard no_grad;
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    const auto& [name, tensor] = parameters[i];
    const StoredParameter& stored = contents.parameters[i];
    require(stored.shape == tensor.sizes().vec(),
            "parameter '" + name + "' has shape " + shape_text(stored.shape) +
                " in the file, the architecture " + shape_text(tensor.sizes().vec()),
            file);
    torch::Tensor target = tensor;
    target.copy_(
        torch::from_blob(const_cast<float*>(stored.values.data()), tensor.sizes(), torch::kFloat));
  }
  return model;
}

}  // namespace tendril::dynamics
