#pragma once

#include <string>
#include <string_view>

namespace tendril::nn {

// Hidden-layer non-linearity of a multilayer perceptron.
enum class Activation { kTanh, kRelu };

// "tanh" or "relu"; anything else raises Error naming `where`.
Activation parse_activation(std::string_view name, const std::string& where);
std::string activation_name(Activation activation);

}  // namespace tendril::nn
