#include "tendril/nn/activation.hpp"

#include "tendril/core/error.hpp"

namespace tendril::nn {

Activation parse_activation(std::string_view name, const std::string& where) {
  if (name == "tanh") return Activation::kTanh;
  if (name == "relu") return Activation::kRelu;
  throw Error("unknown activation '" + std::string(name) + "', expected tanh or relu", where);
}

std::string activation_name(Activation activation) {
  return activation == Activation::kTanh ? "tanh" : "relu";
}

}  // namespace tendril::nn
