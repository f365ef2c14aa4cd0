#include "tendril/dynamics/fused_lstm.hpp"

#include <Eigen/Core>
#include <algorithm>

#include "tendril/core/error.hpp"

namespace tendril::dynamics {

namespace {

using torch::Tensor;
using torch::autograd::AutogradContext;
using torch::autograd::variable_list;
using Rows = Eigen::Array<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using RowsMap = Eigen::Map<Rows>;

RowsMap rows(Tensor& tensor, int64_t count, int64_t width) {
  return RowsMap(tensor.data_ptr<float>(), count, width);
}

// One step's gates [B, 4H] (pre-activations in, activations out) given c_{t−1}; writes c_t,
// tanh(c_t) and h_t.
void cell_forward(Tensor gates, const Tensor& c_previous, Tensor cell, Tensor tanh_cell,
                  Tensor hidden, int64_t batch, int64_t h) {
  RowsMap g = rows(gates, batch, 4 * h);
  g.leftCols(2 * h) = g.leftCols(2 * h).logistic();
  g.middleCols(2 * h, h) = g.middleCols(2 * h, h).tanh();
  g.rightCols(h) = g.rightCols(h).logistic();
  const RowsMap c0(const_cast<float*>(c_previous.data_ptr<float>()), batch, h);
  RowsMap c = rows(cell, batch, h), tc = rows(tanh_cell, batch, h), out = rows(hidden, batch, h);
  c = g.middleCols(h, h) * c0 + g.leftCols(h) * g.middleCols(2 * h, h);
  tc = c.tanh();
  out = g.rightCols(h) * tc;
}

// Backward through one step: from dL/dh_t (total) and dL/dc_t (from step t+1) to the gates'
// pre-activation gradients [B, 4H] and dL/dc_{t−1} (written over `dc`).
void cell_backward(const Tensor& activations, const Tensor& c_previous, const Tensor& tanh_cell,
                   const Tensor& dh, Tensor dc, Tensor dgates, int64_t batch, int64_t h) {
  const RowsMap a(const_cast<float*>(activations.data_ptr<float>()), batch, 4 * h);
  const RowsMap c0(const_cast<float*>(c_previous.data_ptr<float>()), batch, h);
  const RowsMap tc(const_cast<float*>(tanh_cell.data_ptr<float>()), batch, h);
  const RowsMap d_h(const_cast<float*>(dh.data_ptr<float>()), batch, h);
  RowsMap d_c = rows(dc, batch, h), dg = rows(dgates, batch, 4 * h);
  const auto i = a.leftCols(h), f = a.middleCols(h, h), g = a.middleCols(2 * h, h),
             o = a.rightCols(h);
  const Rows dct = d_c + d_h * o * (1.0f - tc.square());
  dg.leftCols(h) = dct * g * i * (1.0f - i);
  dg.middleCols(h, h) = dct * c0 * f * (1.0f - f);
  dg.middleCols(2 * h, h) = dct * i * (1.0f - g.square());
  dg.rightCols(h) = d_h * tc * o * (1.0f - o);
  d_c = dct * f;
}

// Every step's activations, cell states and outputs per layer, for the backward pass.
struct SavedSteps {
  std::vector<Tensor> inputs, activations, cells, tanh_cells, hidden;
};

// The forward pass through the stack: outputs [B, T, H], h_n, c_n. With `saved`, keeps what the
// backward pass needs; without (no gradient wanted), only two cell states per layer.
variable_list forward_pass(const Tensor& input, const Tensor& h0, const Tensor& c0,
                           torch::TensorList weights, SavedSteps* saved) {
  const int64_t layers = static_cast<int64_t>(weights.size()) / 4;
  const int64_t batch = input.size(0), steps = input.size(1), h = weights[1].size(1);
  Tensor layer_input = input.transpose(0, 1).contiguous();  // [T, B, F]
  std::vector<Tensor> h_n, c_n;
  for (int64_t l = 0; l < layers; ++l) {
    const Tensor bias = weights[4 * l + 2] + weights[4 * l + 3];
    // The input projections of all steps at once; each step then adds W_hh h_{t−1}.
    Tensor activations =
        torch::addmm(bias, layer_input.view({steps * batch, -1}), weights[4 * l].t())
            .view({steps, batch, 4 * h});
    const int64_t kept = saved ? steps : 2;
    Tensor cells = torch::empty({kept, batch, h});
    Tensor tanh_cells = torch::empty({kept, batch, h});
    Tensor hidden = torch::empty({steps, batch, h});
    const Tensor w_hh_t = weights[4 * l + 1].t();
    for (int64_t t = 0; t < steps; ++t) {
      Tensor gates = activations[t];
      gates.addmm_(t > 0 ? hidden[t - 1] : h0[l], w_hh_t);
      const Tensor c_previous = t > 0 ? cells[(t - 1) % kept] : c0[l];
      cell_forward(gates, c_previous, cells[t % kept], tanh_cells[t % kept], hidden[t], batch, h);
    }
    h_n.push_back(hidden[steps - 1]);
    c_n.push_back(cells[(steps - 1) % kept]);
    if (saved) {
      saved->inputs.push_back(layer_input);
      saved->activations.push_back(activations);
      saved->cells.push_back(cells);
      saved->tanh_cells.push_back(tanh_cells);
      saved->hidden.push_back(hidden);
    }
    layer_input = hidden;
  }
  return {layer_input.transpose(0, 1).contiguous(), torch::stack(h_n), torch::stack(c_n)};
}

class FusedLstm : public torch::autograd::Function<FusedLstm> {
 public:
  // weights: w_ih, w_hh, b_ih, b_hh per layer.
  static variable_list forward(AutogradContext* ctx, Tensor input, Tensor h0, Tensor c0,
                               torch::TensorList weights) {
    SavedSteps saved;
    variable_list outputs = forward_pass(input, h0, c0, weights, &saved);
    ctx->save_for_backward(weights.vec());
    ctx->saved_data["h0"] = h0;
    ctx->saved_data["c0"] = c0;
    ctx->saved_data["inputs"] = saved.inputs;
    ctx->saved_data["activations"] = saved.activations;
    ctx->saved_data["cells"] = saved.cells;
    ctx->saved_data["tanh"] = saved.tanh_cells;
    ctx->saved_data["hidden"] = saved.hidden;
    return outputs;
  }

  static variable_list backward(AutogradContext* ctx, variable_list grads) {
    const variable_list weights = ctx->get_saved_variables();
    const Tensor h0 = ctx->saved_data["h0"].toTensor();
    const Tensor c0 = ctx->saved_data["c0"].toTensor();
    const auto inputs = ctx->saved_data["inputs"].toTensorVector();
    const auto activations = ctx->saved_data["activations"].toTensorVector();
    const auto cells = ctx->saved_data["cells"].toTensorVector();
    const auto tanh_cells = ctx->saved_data["tanh"].toTensorVector();
    const auto hidden = ctx->saved_data["hidden"].toTensorVector();
    const int64_t layers = static_cast<int64_t>(weights.size()) / 4;
    const int64_t steps = hidden[0].size(0), batch = hidden[0].size(1), h = hidden[0].size(2);

    // dL/d(outputs of the current layer), time-major.
    Tensor d_output = grads[0].defined() ? grads[0].transpose(0, 1).contiguous()
                                         : torch::zeros({steps, batch, h});
    variable_list weight_grads(weights.size());
    std::vector<Tensor> d_h0(layers), d_c0(layers);
    Tensor d_input;
    for (int64_t l = layers - 1; l >= 0; --l) {
      const Tensor& w_ih = weights[4 * l];
      const Tensor& w_hh = weights[4 * l + 1];
      Tensor dh = grads[1].defined() ? grads[1][l].clone(at::MemoryFormat::Contiguous)
                                     : torch::zeros({batch, h});
      Tensor dc = grads[2].defined() ? grads[2][l].clone(at::MemoryFormat::Contiguous)
                                     : torch::zeros({batch, h});
      Tensor dgates = torch::empty({steps, batch, 4 * h});
      Tensor dh_total = torch::empty({batch, h});
      for (int64_t t = steps - 1; t >= 0; --t) {
        torch::add_out(dh_total, d_output[t], dh);
        const Tensor c_previous = t > 0 ? cells[l][t - 1] : c0[l];
        cell_backward(activations[l][t], c_previous.contiguous(), tanh_cells[l][t], dh_total, dc,
                      dgates[t], batch, h);
        torch::mm_out(dh, dgates[t], w_hh);
      }
      d_h0[l] = dh;
      d_c0[l] = dc;
      const Tensor flat = dgates.view({steps * batch, 4 * h});
      const Tensor h_previous =
          torch::cat({h0[l].unsqueeze(0), hidden[l].narrow(0, 0, steps - 1)}, 0)
              .view({steps * batch, h});
      weight_grads[4 * l] = flat.t().mm(inputs[l].view({steps * batch, -1}));
      weight_grads[4 * l + 1] = flat.t().mm(h_previous);
      weight_grads[4 * l + 2] = flat.sum(0);
      weight_grads[4 * l + 3] = weight_grads[4 * l + 2].clone();
      d_input = flat.mm(w_ih).view({steps, batch, -1});
      d_output = d_input;
    }
    variable_list result{d_input.transpose(0, 1).contiguous(), torch::stack(d_h0),
                         torch::stack(d_c0)};
    result.insert(result.end(), weight_grads.begin(), weight_grads.end());
    return result;
  }
};

}  // namespace

std::tuple<Tensor, Tensor, Tensor> fused_lstm(const torch::nn::LSTM& lstm, const Tensor& input,
                                              const Tensor& h0, const Tensor& c0) {
  const auto& options = lstm->options;
  require(options.batch_first() && !options.bidirectional() && options.bias() &&
              options.proj_size() == 0,
          "needs a batch-first, unidirectional LSTM with biases", "dynamics::fused_lstm");
  const int64_t layers = options.num_layers(), h = options.hidden_size();
  const int64_t batch = input.size(0);
  const Tensor zeros = torch::zeros({layers, batch, h});
  const std::vector<Tensor> weights = lstm->all_weights();
  const Tensor x = input.contiguous();
  const Tensor h_start = h0.defined() ? h0.contiguous() : zeros;
  const Tensor c_start = c0.defined() ? c0.contiguous() : zeros;
  const bool wants_gradient =
      torch::GradMode::is_enabled() &&
      (x.requires_grad() || h_start.requires_grad() || c_start.requires_grad() ||
       std::any_of(weights.begin(), weights.end(),
                   [](const Tensor& w) { return w.requires_grad(); }));
  if (!wants_gradient) {
    torch::NoGradGuard no_grad;
    const variable_list out = forward_pass(x, h_start, c_start, weights, nullptr);
    return {out[0], out[1], out[2]};
  }
  // A TensorList (not a vector) makes every weight an input of the autograd node.
  const variable_list out = FusedLstm::apply(x, h_start, c_start, torch::TensorList(weights));
  return {out[0], out[1], out[2]};
}

}  // namespace tendril::dynamics
