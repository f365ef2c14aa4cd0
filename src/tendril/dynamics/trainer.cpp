#include "tendril/dynamics/trainer.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>

#include "tendril/core/error.hpp"
#include "tendril/core/interrupt.hpp"
#include "tendril/core/progress_clock.hpp"

namespace tendril::dynamics {

namespace {

using Clock = std::chrono::steady_clock;

std::string key(const Config& config, const std::string& name) {
  return config.source() + ": " + (config.path().empty() ? name : config.path() + "." + name);
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

// The fit's state at an epoch's end, what train_model needs to continue exactly.
struct FitState {
  int next_epoch = 0;
  int64_t trained = 0;
  std::vector<int64_t> order;  // the train windows as the last shuffle left them
  std::vector<torch::Tensor> best;
  TrainingReport report;
};

torch::Tensor rng_tensor(const Rng& rng) {
  const Rng::State& state = rng.state();
  std::vector<int64_t> words(state.words.begin(), state.words.end());
  words.push_back(state.has_spare_normal ? 1 : 0);
  int64_t spare = 0;
  std::memcpy(&spare, &state.spare_normal, sizeof spare);
  words.push_back(spare);
  return torch::tensor(words, torch::kInt64);
}

Rng rng_from(const torch::Tensor& tensor, const std::string& where) {
  require(tensor.numel() == 6, "a random stream of the wrong size", where);
  const auto* words = tensor.data_ptr<int64_t>();
  Rng::State state;
  for (int i = 0; i < 4; ++i) state.words[i] = static_cast<uint64_t>(words[i]);
  state.has_spare_normal = words[4] != 0;
  std::memcpy(&state.spare_normal, &words[5], sizeof state.spare_normal);
  Rng rng;
  rng.set_state(state);
  return rng;
}

void save_fit_state(const std::filesystem::path& file, SequenceNetwork& network,
                    torch::optim::Adam& adam, const Rng& order_rng, const FitState& fit) {
  torch::serialize::OutputArchive archive;
  torch::serialize::OutputArchive weights, optimizer, best;
  network.save(weights);
  adam.save(optimizer);
  for (std::size_t i = 0; i < fit.best.size(); ++i) best.write(std::to_string(i), fit.best[i]);
  archive.write("weights", weights);
  archive.write("adam", optimizer);
  archive.write("best", best);
  archive.write("best_count", static_cast<int64_t>(fit.best.size()));
  archive.write("order", torch::tensor(fit.order, torch::kInt64));
  archive.write("order_rng", rng_tensor(order_rng));
  archive.write("noise_rng", rng_tensor(network.noise()));
  archive.write("next_epoch", static_cast<int64_t>(fit.next_epoch));
  archive.write("trained", fit.trained);
  archive.write("best_epoch", static_cast<int64_t>(fit.report.best_epoch));
  archive.write("best_validation_loss", fit.report.best_validation_loss);
  archive.write("final_train_loss", fit.report.final_train_loss);
  archive.write("seconds", fit.report.seconds);
  // Written beside, then renamed: a kill mid-write leaves the previous state or none.
  const std::filesystem::path partial = file.string() + ".partial";
  archive.save_to(partial.string());
  std::filesystem::rename(partial, file);
}

void open_fit_state(const std::filesystem::path& file, torch::serialize::InputArchive& archive) {
  try {
    archive.load_from(file.string());
  } catch (const c10::Error& e) {
    throw Error("not a readable fit checkpoint (" + std::string(e.what_without_backtrace()) + ")",
                file.string());
  }
}

// One scalar of a fit checkpoint.
c10::IValue scalar(torch::serialize::InputArchive& archive, const char* key) {
  c10::IValue value;
  archive.read(key, value);
  return value;
}

FitState load_fit_state(const std::filesystem::path& file, SequenceNetwork& network,
                        torch::optim::Adam& adam, Rng& order_rng) {
  const std::string where = file.string();
  torch::serialize::InputArchive archive;
  open_fit_state(file, archive);
  const auto integer = [&](const char* key) { return scalar(archive, key).toInt(); };
  const auto real = [&](const char* key) { return scalar(archive, key).toDouble(); };
  torch::serialize::InputArchive weights, optimizer, best;
  archive.read("weights", weights);
  archive.read("adam", optimizer);
  archive.read("best", best);
  network.load(weights);
  adam.load(optimizer);
  FitState fit;
  for (int64_t i = 0, n = integer("best_count"); i < n; ++i) {
    torch::Tensor tensor;
    best.read(std::to_string(i), tensor);
    fit.best.push_back(tensor);
  }
  torch::Tensor order, order_words, noise_words;
  archive.read("order", order);
  archive.read("order_rng", order_words);
  archive.read("noise_rng", noise_words);
  fit.order.assign(order.data_ptr<int64_t>(), order.data_ptr<int64_t>() + order.numel());
  order_rng = rng_from(order_words, where);
  network.set_noise(rng_from(noise_words, where));
  fit.next_epoch = static_cast<int>(integer("next_epoch"));
  fit.trained = integer("trained");
  fit.report.best_epoch = static_cast<int>(integer("best_epoch"));
  fit.report.best_validation_loss = real("best_validation_loss");
  fit.report.final_train_loss = real("final_train_loss");
  fit.report.seconds = real("seconds");
  fit.report.epochs_run = fit.next_epoch;
  return fit;
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

int checkpoint_epochs(const std::filesystem::path& checkpoint_file) {
  torch::serialize::InputArchive archive;
  open_fit_state(checkpoint_file, archive);
  return static_cast<int>(scalar(archive, "next_epoch").toInt());
}

TrainingReport train_model(Model& model, const WindowSet& windows, const TrainingOptions& options,
                           uint64_t seed, const std::function<void(const EpochReport&)>& on_epoch,
                           bool quiet, const std::filesystem::path& checkpoint_file) {
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
  int first_epoch = 0;
  double earlier_seconds = 0.0;  // of the fit before the checkpoint it continues from
  if (!checkpoint_file.empty() && std::filesystem::exists(checkpoint_file)) {
    FitState fit = load_fit_state(checkpoint_file, network, adam, order);
    require(fit.order.size() == train.size(),
            "the checkpoint holds " + std::to_string(fit.order.size()) + " training windows, the " +
                "data gives " + std::to_string(train.size()) + " (another data set?)",
            checkpoint_file.string());
    train = std::move(fit.order);
    best = std::move(fit.best);
    trained = fit.trained;
    first_epoch = fit.next_epoch;
    earlier_seconds = fit.report.seconds;
    report.best_epoch = fit.report.best_epoch;
    report.best_validation_loss = fit.report.best_validation_loss;
    report.final_train_loss = fit.report.final_train_loss;
    report.epochs_run = fit.report.epochs_run;
  }
  const int64_t trained_before = trained;
  const auto start = Clock::now() - std::chrono::duration_cast<Clock::duration>(
                                        std::chrono::duration<double>(earlier_seconds));
  auto last_print = Clock::now() - std::chrono::seconds(2);
  for (int epoch = first_epoch; epoch < options.epochs; ++epoch) {
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
        const double elapsed = std::chrono::duration<double>(now - start).count() - earlier_seconds;
        const double rate = static_cast<double>(trained - trained_before) / elapsed;
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
    if (!checkpoint_file.empty() && interrupt_signal() != 0 && epoch + 1 < options.epochs) {
      report.seconds = epoch_report.seconds;
      report.windows_per_second = static_cast<double>(trained) / std::max(report.seconds, 1e-9);
      save_fit_state(checkpoint_file, network, adam, order,
                     FitState{epoch + 1, trained, train, best, report});
      report.interrupted = interrupt_signal();
      network.eval();
      if (!quiet) std::fputc('\n', stderr);
      return report;
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
