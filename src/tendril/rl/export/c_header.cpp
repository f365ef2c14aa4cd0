#include "tendril/rl/export/c_header.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "tendril/core/atomic_file.hpp"
#include "tendril/core/error.hpp"

namespace tendril::rl {

namespace {

bool is_c_identifier(const std::string& name) {
  if (name.empty() || std::isdigit(static_cast<unsigned char>(name[0]))) return false;
  return std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  });
}

std::string upper(std::string text) {
  for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return text;
}

// A float literal that reads back as exactly `value` (9 significant digits round-trip a float);
// an infinite bound becomes the largest float, which clips every finite value the same way.
std::string literal(float value) {
  if (std::isinf(value)) value = std::copysign(std::numeric_limits<float>::max(), value);
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", static_cast<double>(value));
  std::string out = text;
  if (out.find_first_of(".e") == std::string::npos) out += ".0";
  return out + "f";
}

void write_array(std::ostringstream& out, const std::string& macro, const std::string& name,
                 const std::vector<float>& values) {
  out << "static const float " << name << "[" << values.size() << "] " << macro << "_FLASH = {";
  for (std::size_t i = 0; i < values.size(); ++i) {
    out << (i % 6 == 0 ? "\n    " : " ") << literal(values[i])
        << (i + 1 < values.size() ? "," : "");
  }
  out << "\n};\n";
}

int activation_code(PolicyNetwork::Activation activation) {
  return static_cast<int>(activation);  // the switch of <name>_dense below
}

std::string shape_text(const PolicyNetwork& network) {
  std::ostringstream text;
  text << network.observation_size;
  for (const PolicyNetwork::Layer& layer : network.layers) {
    text << " -> " << layer.outputs;
    if (layer.activation != PolicyNetwork::Activation::kNone) {
      text << " " << activation_name(layer.activation);
    }
  }
  return text.str();
}

}  // namespace

std::string c_header(const PolicyNetwork& network, const std::string& name,
                     const std::string& description) {
  require(is_c_identifier(name), "'" + name + "' is not a C identifier (letters, digits, _)",
          "policy export name");
  const std::string macro = upper(name);
  const bool normalized = !network.mean.empty();
  const bool discrete = network.output == PolicyNetwork::Output::kArgmax;
  // Two buffers in turn: `a` holds the observation and the outputs of layers 1, 3, …, `b` those
  // of layers 0, 2, …; each as large as the most it holds (RAM is scarce on a microcontroller).
  int64_t size_a = network.observation_size, size_b = 1;
  for (std::size_t k = 0; k < network.layers.size(); ++k) {
    int64_t& size = k % 2 == 0 ? size_b : size_a;
    size = std::max(size, network.layers[k].outputs);
  }
  std::ostringstream out;
  out << "/* " << name << ".h: a trained policy as plain C, written by tendril's policy export.\n"
      << " *   " << description << "\n"
      << " *   kind " << network.kind << "; layers " << shape_text(network) << "; output "
      << output_name(network.output) << "; " << network.parameter_count() << " parameters"
      << (normalized ? "; observation normalization" : "") << "\n"
      << " *\n"
      << " *   float action[" << macro << "_ACTION_SIZE];\n"
      << " *   " << name << "_act(observation, action);\n"
      << " *\n"
      << " * The policy's deterministic action for a raw observation (" << network.observation_size
      << " floats), computed as\n"
      << " * tendril computes it: normalization, layers, then the action's "
      << (discrete ? "argmax (the index of the\n * largest output, as a float)"
                   : "squash and scaling into\n * the action space's bounds")
      << ". Needs only <math.h>; with avr-gcc the weights stay in flash. */\n"
      << "#ifndef " << macro << "_H_\n#define " << macro << "_H_\n\n#include <math.h>\n\n"
      << "#ifdef __AVR__\n#include <avr/pgmspace.h>\n#define " << macro
      << "_FLASH PROGMEM\n#define " << macro << "_READ(x) pgm_read_float(&(x))\n#else\n#define "
      << macro << "_FLASH\n#define " << macro << "_READ(x) (x)\n#endif\n\n"
      << "#define " << macro << "_OBSERVATION_SIZE " << network.observation_size << "\n"
      << "#define " << macro << "_ACTION_SIZE " << network.action_size << "\n";
  if (discrete) out << "#define " << macro << "_ACTION_CHOICES " << network.action_choices << "\n";
  out << "#define " << macro << "_PARAMETER_COUNT " << network.parameter_count() << "L\n\n";

  if (normalized) {
    out << "/* clip((observation - mean) * scale, +-" << literal(network.clip)
        << "), scale = 1 / sqrt(var + eps) */\n";
    write_array(out, macro, name + "_mean", network.mean);
    write_array(out, macro, name + "_scale", network.scale);
  }
  for (std::size_t k = 0; k < network.layers.size(); ++k) {
    const PolicyNetwork::Layer& layer = network.layers[k];
    out << "/* layer " << k << ": " << layer.inputs << " -> " << layer.outputs << ", "
        << activation_name(layer.activation) << "; weight row-major (outputs x inputs) */\n";
    write_array(out, macro, name + "_weight" + std::to_string(k), layer.weight);
    write_array(out, macro, name + "_bias" + std::to_string(k), layer.bias);
  }
  if (!discrete) {
    write_array(out, macro, name + "_low", network.low);
    write_array(out, macro, name + "_high", network.high);
  }

  // One dense layer: y = activation(W x + b), W read row by row (no index products, which
  // would overflow AVR's 16-bit int on wide layers).
  out << "\nstatic void " << name
      << "_dense(const float *weight, const float *bias, int inputs, int outputs,\n"
      << "    const float *x, float *y, int activation) {\n"
      << "  int r, c;\n"
      << "  for (r = 0; r < outputs; ++r) {\n"
      << "    float sum = 0.0f;\n"
      << "    for (c = 0; c < inputs; ++c) sum += " << macro << "_READ(weight[c]) * x[c];\n"
      << "    weight += inputs;\n"
      << "    sum += " << macro << "_READ(bias[r]);\n"
      << "    if (activation == " << activation_code(PolicyNetwork::Activation::kTanh)
      << ") sum = (float)tanh(sum);\n"
      << "    else if (activation == " << activation_code(PolicyNetwork::Activation::kRelu)
      << ") sum = sum > 0.0f ? sum : 0.0f;\n"
      << "    else if (activation == " << activation_code(PolicyNetwork::Activation::kSoftsign)
      << ") sum = sum / (1.0f + (float)fabs(sum));\n"
      << "    y[r] = sum;\n"
      << "  }\n}\n\n";

  out << "static void " << name << "_act(const float *observation, float *action) {\n"
      << "  float a[" << size_a << "], b[" << size_b << "];\n"
      << "  int i;\n"
      << "  for (i = 0; i < " << network.observation_size << "; ++i) {\n";
  if (normalized) {
    out << "    float v = (observation[i] - " << macro << "_READ(" << name << "_mean[i])) * "
        << macro << "_READ(" << name << "_scale[i]);\n"
        << "    a[i] = v < -" << literal(network.clip) << " ? -" << literal(network.clip)
        << " : (v > " << literal(network.clip) << " ? " << literal(network.clip) << " : v);\n";
  } else {
    out << "    a[i] = observation[i];\n";
  }
  out << "  }\n";
  for (std::size_t k = 0; k < network.layers.size(); ++k) {
    const PolicyNetwork::Layer& layer = network.layers[k];
    const char* from = k % 2 == 0 ? "a" : "b";
    const char* to = k % 2 == 0 ? "b" : "a";
    out << "  " << name << "_dense(" << name << "_weight" << k << ", " << name << "_bias" << k
        << ", " << layer.inputs << ", " << layer.outputs << ", " << from << ", " << to << ", "
        << activation_code(layer.activation) << ");\n";
  }
  const char* result = network.layers.size() % 2 == 1 ? "b" : "a";
  if (discrete) {
    out << "  {\n    int best = 0;\n"
        << "    for (i = 1; i < " << network.action_choices << "; ++i) if (" << result << "[i] > "
        << result << "[best]) best = i;\n"
        << "    action[0] = (float)best;\n  }\n";
  } else {
    out << "  for (i = 0; i < " << network.action_size << "; ++i) {\n"
        << "    float low = " << macro << "_READ(" << name << "_low[i]), high = " << macro
        << "_READ(" << name << "_high[i]);\n"
        << "    float v = " << result << "[i];\n";
    if (network.output == PolicyNetwork::Output::kClip) {
      out << "    action[i] = v < low ? low : (v > high ? high : v);\n";
    } else {
      if (network.output == PolicyNetwork::Output::kClampTanhScale) {
        out << "    v = (float)tanh(v < -2.0f ? -2.0f : (v > 2.0f ? 2.0f : v));\n";
      }
      out << "    v = v < -1.0f ? -1.0f : (v > 1.0f ? 1.0f : v);\n"
          << "    action[i] = low + (v + 1.0f) * (0.5f * (high - low));\n";
    }
    out << "  }\n";
  }
  out << "}\n\n#endif /* " << macro << "_H_ */\n";
  return out.str();
}

void write_c_header(const Policy& policy, const std::filesystem::path& file,
                    const std::string& name, const std::string& description) {
  write_new_file_atomically(file, c_header(policy_network(policy), name, description), "C header");
}

}  // namespace tendril::rl
