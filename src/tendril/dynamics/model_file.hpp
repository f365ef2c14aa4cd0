#pragma once

#include <filesystem>
#include <memory>

namespace tendril::dynamics {

class Model;

// A trained model in one self-describing file; the layout is in model_file_format.hpp, which
// reads and writes it without LibTorch. The file alone rebuilds the model: no experiment file is
// needed.
inline constexpr const char* kModelFileName = "model.tdm";
// A fit's run directory holds kModelFileName, and while the fit is stopped with a checkpoint
// (fit_run.hpp) this file; both names are torch-free, so the command line finds fit runs without
// loading the layer.
inline constexpr const char* kFitCheckpointName = "fit.ckpt";

// Writes `model` to `file` atomically. Raises Error if `file` exists, unless `replace` (a run
// replacing its own model when validation improves): nothing else is ever overwritten.
void save_model(const Model& model, const std::filesystem::path& file, bool replace = false);

// Reads a model file, or a run directory's model.tdm. A missing, truncated or corrupt file, an
// unknown format version, or parameters that do not match the architecture the header
// describes raise Error naming the file and what is wrong.
std::unique_ptr<Model> load_model(const std::filesystem::path& file_or_run);

// `path` itself, or `path`/model.tdm when `path` is a directory.
std::filesystem::path model_file_path(const std::filesystem::path& file_or_run);

}  // namespace tendril::dynamics
