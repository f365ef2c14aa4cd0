#include "tendril/nn/activation.hpp"

#include "tendril/core/error.hpp"

namespace tendril::nn {

Activation parse_activation(std::string_view name, const std::string& where) {
  if (name == "tanh") return Activation::kTanh;
  if (name == "relu") return Activation::kRelu;
  if (name == "softsign") return Activation::kSoftsign;
  throw Error("unknown activation '" + std::string(name) + "', expected tanh, relu or softsign",
              where);
}

std::string activation_name(Activation activation) {
  switch (activation) {
    case Activation::kTanh:
      return "tanh";
    case Activation::kRelu:
      return "relu";
    case Activation::kSoftsign:
      return "softsign";
  }
  return "tanh";
}

}  // namespace tendril::nn
