#include "tendril/dynamics/trainer.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "tendril/core/error.hpp"

namespace tendril::dynamics {

namespace {

using Clock = std::chrono::steady_clock;

std::string key(const Config& config, const std::string& name) {
  return config.source() + ": " + (config.path().empty() ? name : config.path() + "." + name);
}

std::string duration_text(double seconds) {
  const auto total = static_cast<long long>(seconds + 0.5);
  char text[32];
  if (total >= 3600) {
    std::snprintf(text, sizeof text, "%lldh%02lldm", total / 3600, total / 60 % 60);
  } else {
    std::snprintf(text, sizeof text, "%lldm%02llds", total / 60, total % 60);
  }
  return text;
}

std::string best_text(const TrainingReport& report) {
  if (std::isnan(report.best_validation_loss)) return "-";
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", report.best_validation_loss);
  return text;
}

void shuffle(std::vector<int64_t>& values, Rng& rng) {
  for (std::size_t i = values.size(); i > 1; --i) {
    std::swap(values[i - 1], values[rng.below(i)]);
  }
}

// Copies of every parameter, to keep the best weights.
std::vector<torch::Tensor> snapshot(SequenceNetwork& network) {
  std::vector<torch::Tensor> copies;
  for (const auto& parameter : network.parameters()) copies.push_back(parameter.detach().clone());
  return copies;
}

void restore(SequenceNetwork& network, const std::vector<torch::Tensor>& copies) {
  torch::NoGradGuard no_grad;
  const auto parameters = network.parameters();
  for (std::size_t i = 0; i < parameters.size(); ++i) parameters[i].copy_(copies[i]);
}

double mean_loss(Model& model, const WindowSet& windows, std::span<const int64_t> ends,
                 int batch_size) {
  torch::NoGradGuard no_grad;
  model.network().eval();
  double sum = 0.0;
  for (std::size_t begin = 0; begin < ends.size(); begin += static_cast<std::size_t>(batch_size)) {
    const auto batch = ends.subspan(begin, std::min<std::size_t>(batch_size, ends.size() - begin));
    const torch::Tensor output =
        model.network().forward(model.network_input(windows.windows(batch)));
    sum += torch::mse_loss(output, windows.targets(batch), at::Reduction::Sum).item<double>();
  }
  return sum / (static_cast<double>(ends.size()) * model.state_dim());
}

}  // namespace

TrainingOptions TrainingOptions::from_config(const Config& training) {
  TrainingOptions o;
  o.epochs = training.get_or<int>("epochs", o.epochs);
  o.batch_size = training.get_or<int>("batch_size", o.batch_size);
  o.learning_rate = training.get_or<double>("learning_rate", o.learning_rate);
  o.final_learning_rate = training.get_or<double>("final_learning_rate", o.learning_rate);
  o.grad_clip_value = training.get_or<double>("grad_clip_value", o.grad_clip_value);
  o.validation_fraction = training.get_or<double>("validation_fraction", o.validation_fraction);
  o.patience = training.get_or<int>("patience", o.patience);
  o.windows_per_epoch = training.get_or<int64_t>("windows_per_epoch", o.windows_per_epoch);
  require(o.epochs >= 0, "must not be negative", key(training, "epochs"));
  require(o.batch_size >= 1, "must be at least 1", key(training, "batch_size"));
  require(o.learning_rate >= 0.0 && o.final_learning_rate >= 0.0, "must not be negative",
          key(training, "learning_rate"));
  require(o.grad_clip_value >= 0.0, "must not be negative", key(training, "grad_clip_value"));
  require(o.validation_fraction >= 0.0 && o.validation_fraction < 1.0, "must lie in [0, 1)",
          key(training, "validation_fraction"));
  require(o.patience >= 0, "must not be negative", key(training, "patience"));
  require(o.windows_per_epoch >= 0, "must not be negative", key(training, "windows_per_epoch"));
  return o;
}

double TrainingOptions::learning_rate_at(int epoch) const {
  if (epochs <= 1 || learning_rate <= 0.0 || final_learning_rate == learning_rate) {
    return learning_rate;
  }
  const double progress = static_cast<double>(epoch) / static_cast<double>(epochs - 1);
  return learning_rate * std::pow(final_learning_rate / learning_rate, progress);
}

TrainingReport train_model(Model& model, const WindowSet& windows, const TrainingOptions& options,
                           uint64_t seed, const std::function<void(const EpochReport&)>& on_epoch,
                           bool quiet) {
  // The latest windows of the training data are held out for validation (neighbouring windows
  // share all but one row, so a random hold-out would leak).
  const std::vector<int64_t>& all = windows.ends(Split::kTrain);
  const auto validation_size = static_cast<std::size_t>(
      std::floor(options.validation_fraction * static_cast<double>(all.size())));
  std::vector<int64_t> train(all.begin(), all.end() - static_cast<std::ptrdiff_t>(validation_size));
  const std::vector<int64_t> validation(all.end() - static_cast<std::ptrdiff_t>(validation_size),
                                        all.end());
  require(!train.empty(), "no training windows (the data is shorter than one window)",
          "dynamics training");

  SequenceNetwork& network = model.network();
  network.set_noise(Rng(seed, 3));
  Rng order(seed, 2);
  torch::optim::Adam adam(network.parameters(), torch::optim::AdamOptions(options.learning_rate));
  const int64_t per_epoch = options.windows_per_epoch > 0
                                ? std::min<int64_t>(options.windows_per_epoch, train.size())
                                : static_cast<int64_t>(train.size());
  const int64_t batches_per_epoch = (per_epoch + options.batch_size - 1) / options.batch_size;

  TrainingReport report;
  report.train_windows = static_cast<int64_t>(train.size());
  report.validation_windows = static_cast<int64_t>(validation.size());
  report.best_validation_loss = std::numeric_limits<double>::quiet_NaN();
  std::vector<torch::Tensor> best;
  int64_t trained = 0;
  const auto start = Clock::now();
  auto last_print = start - std::chrono::seconds(2);
  for (int epoch = 0; epoch < options.epochs; ++epoch) {
    const double lr = options.learning_rate_at(epoch);
    for (auto& group : adam.param_groups()) {
      static_cast<torch::optim::AdamOptions&>(group.options()).lr(lr);
    }
    shuffle(train, order);
    double loss_sum = 0.0;
    for (int64_t b = 0; b < batches_per_epoch; ++b) {
      const int64_t begin = b * options.batch_size;
      const std::span<const int64_t> batch(
          train.data() + begin, std::min<int64_t>(options.batch_size, per_epoch - begin));
      network.train();
      adam.zero_grad();
      const torch::Tensor output = network.forward(model.network_input(windows.windows(batch)));
      const torch::Tensor loss = torch::mse_loss(output, windows.targets(batch));
      loss.backward();
      if (options.grad_clip_value > 0.0) {
        torch::nn::utils::clip_grad_value_(network.parameters(), options.grad_clip_value);
      }
      adam.step();
      const double value = loss.item<double>();
      require(std::isfinite(value),
              "the training loss became non-finite at epoch " + std::to_string(epoch + 1),
              "dynamics training");
      loss_sum += value;
      trained += static_cast<int64_t>(batch.size());
      const auto now = Clock::now();
      if (!quiet && now - last_print >= std::chrono::seconds(1)) {
        last_print = now;
        const double elapsed = std::chrono::duration<double>(now - start).count();
        const double rate = static_cast<double>(trained) / elapsed;
        const double total = static_cast<double>(per_epoch) * options.epochs;
        std::fprintf(stderr,
                     "\repoch %d/%d  batch %lld/%lld  loss %.4g  best val %s  %.0f windows/s  "
                     "ETA %s   ",
                     epoch + 1, options.epochs, static_cast<long long>(b + 1),
                     static_cast<long long>(batches_per_epoch), value, best_text(report).c_str(),
                     rate, duration_text((total - static_cast<double>(trained)) / rate).c_str());
        std::fflush(stderr);
      }
    }
    EpochReport epoch_report;
    epoch_report.epoch = epoch + 1;
    epoch_report.train_loss = loss_sum / static_cast<double>(batches_per_epoch);
    epoch_report.learning_rate = lr;
    epoch_report.windows = trained;
    epoch_report.validation_loss = std::numeric_limits<double>::quiet_NaN();
    if (!validation.empty()) {
      epoch_report.validation_loss = mean_loss(model, windows, validation, options.batch_size);
      if (!(epoch_report.validation_loss >= report.best_validation_loss)) {
        report.best_validation_loss = epoch_report.validation_loss;
        report.best_epoch = epoch + 1;
        best = snapshot(network);
        epoch_report.improved = true;
      }
    } else {
      report.best_epoch = epoch + 1;
      epoch_report.improved = true;
    }
    epoch_report.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    report.epochs_run = epoch + 1;
    report.final_train_loss = epoch_report.train_loss;
    if (on_epoch) on_epoch(epoch_report);
    if (options.patience > 0 && epoch + 1 - report.best_epoch >= options.patience) {
      report.stopped_early = true;
      break;
    }
  }
  if (!best.empty()) restore(network, best);
  network.eval();
  report.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  report.windows_per_second = static_cast<double>(trained) / std::max(report.seconds, 1e-9);
  if (!quiet && report.epochs_run > 0) std::fputc('\n', stderr);
  return report;
}

}  // namespace tendril::dynamics
