#pragma once

#include <string>
#include <string_view>

namespace tendril::nn {

// Hidden-layer non-linearity of a multilayer perceptron. softsign(x) = x / (1 + |x|) (the actor
// of seed 002 §IV-A, "softsign activation at input, hidden and output layers").
enum class Activation { kTanh, kRelu, kSoftsign };

// "tanh", "relu" or "softsign"; anything else raises Error naming `where`.
Activation parse_activation(std::string_view name, const std::string& where);
std::string activation_name(Activation activation);

}  // namespace tendril::nn
