#pragma once

#include <filesystem>
#include <memory>
#include <string>

namespace tendril::dynamics {

class Model;
struct ModelDescription;

// A trained model in one self-describing file (a Python user can read it without tendril):
//
//   tendril dynamics model\n
//   format 1\n
//   header_bytes <H>\n
//   <H bytes of YAML: architecture, column names, sampling period, normalisation (numbers as the
//    shortest decimal text that reads back exactly), and the parameter table (name, shape)>
//   payload_bytes <P>\n
//   <P bytes: every parameter as little-endian float32, row-major, in the table's order>
//   crc32c <8 hex digits>\n      CRC-32C of every byte before this line
//
// The file alone rebuilds the model: no experiment file is needed.
inline constexpr const char* kModelFileName = "model.tdm";

// Writes `model` to `file` atomically. Raises Error if `file` exists, unless `replace` (a run
// replacing its own model when validation improves): nothing else is ever overwritten.
void save_model(const Model& model, const std::filesystem::path& file, bool replace = false);

// Reads a model file, or a run directory's model.tdm. A missing, truncated or corrupt file, an
// unknown format version, or parameters that do not match the architecture the header
// describes raise Error naming the file and what is wrong.
std::unique_ptr<Model> load_model(const std::filesystem::path& file_or_run);

// A model's description as the file's header writes it (without the parameter table), and
// back; parse_description_yaml raises Error naming `where` on anything missing or invalid.
// Files that carry a model's shape apart from its weights (a policy head) use them.
std::string description_yaml(const ModelDescription& description);
ModelDescription parse_description_yaml(const std::string& yaml, const std::string& where);

// `path` itself, or `path`/model.tdm when `path` is a directory.
std::filesystem::path model_file_path(const std::filesystem::path& file_or_run);

}  // namespace tendril::dynamics
