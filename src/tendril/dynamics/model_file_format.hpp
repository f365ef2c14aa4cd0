#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "tendril/dynamics/model_description.hpp"

namespace tendril::dynamics {

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
// This unit reads and writes the layout without LibTorch; model_file.hpp turns its contents
// into a Model and back.

// One parameter tensor as the file stores it.
struct StoredParameter {
  std::string name;
  std::vector<int64_t> shape;
  std::vector<float> values;  // row-major, as many as the shape's product
};

struct ModelFileContents {
  ModelDescription description;
  std::vector<StoredParameter> parameters;  // in the network's order
};

// The file's bytes for `contents`. Raises Error if a parameter's values do not fill its shape.
std::string encode_model_file(const ModelFileContents& contents);

// Reads a model file's bytes; `file` names it in messages. Framing, checksum, the description,
// and that the parameter table adds up to both the architecture's parameter count and the
// payload are all checked before any parameter storage is allocated, so a damaged or hostile
// header never makes the reader allocate more than the file holds. Raises Error naming the file
// and what is wrong.
ModelFileContents decode_model_file(const std::string& bytes, const std::string& file);

// A model's description as the file's header writes it (without the parameter table), and
// back; parse_description_yaml raises Error naming `where` on anything missing or invalid.
// Files that carry a model's shape apart from its weights (a policy head) use them.
std::string description_yaml(const ModelDescription& description);
ModelDescription parse_description_yaml(const std::string& yaml, const std::string& where);

// The shape as text, "[32, 6]".
std::string shape_text(const std::vector<int64_t>& shape);

}  // namespace tendril::dynamics
