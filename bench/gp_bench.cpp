// Gaussian-process regression: time to fit (with fixed hyper-parameters and with the
// maximum-likelihood search), to predict, and to add a point, against the number of points and
// of input dimensions; and the retrain + prediction of GPRCA's compensator (seed 002: 9-D
// actions to a 9-D error, retrained every 5 steps of a 10 Hz loop). scikit-learn's
// GaussianProcessRegressor runs the same jobs in the same run (bench/gp_bench_sklearn.py: same
// data, kernel, bounds, start and number of restarts; OpenBLAS on one thread, as tendril's Eigen
// code runs on one), and the ratios are printed.
//
//   build/bench/gp_bench            fixed-hyper-parameter fits to 2000 points, searches to 500
//   build/bench/gp_bench --full     searches to 1000 points too (several minutes more)
//   build/bench/gp_bench --quick    a small grid, for a smoke run
//   build/bench/gp_bench --no-sklearn
//
// Data: inputs uniform in [−1, 1]^d, targets Σ_j sin(2x_j + j)/(1 + j/3) + 𝒩(0, 0.1²), 1000
// uniform queries. Fixed hyper-parameters: ℓ = 0.5√d in every dimension, σ_f² = Var y,
// σ_n² = 0.01 Var y. The search starts at ℓ = 1, σ_f² = Var y, σ_n² = 0.01 Var y and at
// `restarts` random points (log-uniform in ℓ ∈ [1e-3, 1e3], σ_f² ∈ [1e-3, 1e3]·Var y,
// σ_n² ∈ [1e-8, 1]·Var y); the two libraries draw their random starts differently, so the log
// marginal likelihood each reaches is printed beside its time.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "tendril/adapt/gaussian_process.hpp"
#include "tendril/adapt/hyperparameter_search.hpp"
#include "tendril/adapt/multi_output_gp.hpp"
#include "tendril/core/rng.hpp"

namespace tendril::adapt {
namespace {

constexpr int kQueries = 1000;
constexpr int kRestarts = 2;
constexpr int kGprcaDim = 9;

using Clock = std::chrono::steady_clock;

double median_seconds(const std::function<void()>& action, int min_repeats = 3,
                      double min_total = 0.3) {
  std::vector<double> times;
  double total = 0.0;
  while (static_cast<int>(times.size()) < min_repeats || total < min_total) {
    const auto start = Clock::now();
    action();
    times.push_back(std::chrono::duration<double>(Clock::now() - start).count());
    total += times.back();
  }
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

struct Data {
  Eigen::MatrixXd inputs, targets, queries;  // targets n × outputs
  double target_variance(int output = 0) const {
    const auto y = targets.col(output).array();
    return (y - y.mean()).square().mean();
  }
};

Data make_data(int n, int d, int outputs, uint64_t seed) {
  Rng rng(seed);
  Data data{Eigen::MatrixXd(n, d), Eigen::MatrixXd(n, outputs), Eigen::MatrixXd(kQueries, d)};
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < d; ++j) data.inputs(i, j) = rng.uniform(-1.0, 1.0);
    for (int k = 0; k < outputs; ++k) {
      double value = 0.0;
      for (int j = 0; j < d; ++j)
        value += std::sin(2.0 * data.inputs(i, j) + j + k) / (1.0 + j / 3.0);
      data.targets(i, k) = value + 0.1 * rng.normal();
    }
  }
  for (int i = 0; i < kQueries; ++i) {
    for (int j = 0; j < d; ++j) data.queries(i, j) = rng.uniform(-1.0, 1.0);
  }
  return data;
}

// Row-major float64: inputs, targets, queries (what gp_bench_sklearn.py reads).
void write_data(const std::filesystem::path& file, const Data& data) {
  std::ofstream out(file, std::ios::binary);
  for (const Eigen::MatrixXd* m : {&data.inputs, &data.targets, &data.queries}) {
    const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> rows = *m;
    out.write(reinterpret_cast<const char*>(rows.data()), sizeof(double) * rows.size());
  }
}

struct Job {
  std::string id, kind, kernel;
  int n, d, restarts;
  double length_scale, constant, noise;  // constant and noise relative to Var y
};

struct SklearnResult {
  double first_seconds = 0, second_seconds = 0, log_likelihood = 0;
};

// Runs every job through scikit-learn; an empty map when it is not available.
std::map<std::string, SklearnResult> run_sklearn(const std::filesystem::path& directory,
                                                 const std::vector<Job>& jobs) {
  {
    std::ofstream list(directory / "jobs.txt");
    list.precision(17);
    for (const Job& j : jobs) {
      list << j.id << ' ' << j.kind << ' ' << j.kernel << ' ' << j.n << ' ' << j.d << ' '
           << j.restarts << ' ' << j.length_scale << ' ' << j.constant << ' ' << j.noise << '\n';
    }
  }
  const std::string threads = "OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1 MKL_NUM_THREADS=1 ";
  const std::string command = threads +
                              "/usr/bin/python3 " TENDRIL_BENCH_DIR "/gp_bench_sklearn.py " +
                              directory.string() + " > " + (directory / "sklearn.txt").string();
  std::fprintf(stderr, "running scikit-learn's jobs...\n");
  std::map<std::string, SklearnResult> results;
  if (std::system(command.c_str()) != 0) {
    std::fprintf(stderr, "scikit-learn run failed; tendril's figures only\n");
    return results;
  }
  std::ifstream in(directory / "sklearn.txt");
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string id;
    SklearnResult r;
    if (fields >> id >> r.first_seconds >> r.second_seconds >> r.log_likelihood) results[id] = r;
  }
  return results;
}

std::vector<double> read_doubles(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary | std::ios::ate);
  if (!in) return {};
  std::vector<double> values(static_cast<size_t>(in.tellg()) / sizeof(double));
  in.seekg(0);
  in.read(reinterpret_cast<char*>(values.data()), sizeof(double) * values.size());
  return values;
}

std::string ratio(double theirs, double ours) {
  if (theirs <= 0) return "     —";
  char text[32];
  std::snprintf(text, sizeof text, "%6.1f×", theirs / ours);
  return text;
}

GpHyperparameters fixed_hyperparameters(int d, double variance) {
  return {Eigen::VectorXd::Constant(d, 0.5 * std::sqrt(static_cast<double>(d))), variance,
          0.01 * variance};
}

GpHyperparameters search_start(int d, double variance) {
  return {Eigen::VectorXd::Ones(d), variance, 0.01 * variance};
}

std::string search_id(KernelType kernel, int n, int d) {
  return "search_" + kernel_type_name(kernel) + "_" + std::to_string(n) + "_" + std::to_string(d);
}

// log p in the standardised targets' convention scikit-learn reports: + n log σ_y.
double standardised(double log_likelihood, int n, double variance) {
  return log_likelihood + 0.5 * n * std::log(variance);
}

struct GprcaFigures {
  double add_seconds, warm_seconds, cold_seconds, cold_log_likelihood;
};

// GPRCA's compensator on `data` (n + 5 rows): a window of n points retrained every 5 steps.
//   add:  the 5 newest points join (dropping the 5 oldest), then one prediction
//   warm: then the hyper-parameter search from the previous retrain's values, and a prediction
//   cold: a search from the default start on the first n points and a prediction (the job
//         scikit-learn runs); its log marginal likelihood in the standardised convention
GprcaFigures gprca_step(const Data& data, int n, HyperparameterSharing sharing) {
  GpOptions options;
  options.window = n;
  options.restarts = 0;
  MultiOutputGp gp(kGprcaDim, kGprcaDim, options, sharing);
  for (int k = 0; k < kGprcaDim; ++k) {
    gp.output(k).set_hyperparameters(search_start(kGprcaDim, data.target_variance(k)));
  }
  const Eigen::MatrixXd query = data.queries.topRows(1);
  Eigen::MatrixXd mean, variance;
  GprcaFigures figures{};
  Rng rng(2);
  auto start = Clock::now();
  gp.fit(data.inputs.topRows(n), data.targets.topRows(n));
  gp.optimize_hyperparameters(rng);
  gp.predict(query, mean, variance);
  figures.cold_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  for (int k = 0; k < kGprcaDim; ++k) {
    figures.cold_log_likelihood += standardised(gp.output(k).log_marginal_likelihood(), n,
                                                target_scale(gp.output(k).targets()));
  }
  std::vector<double> add_times, warm_times;
  for (int r = 0; r < 5; ++r) {
    MultiOutputGp step = gp;
    start = Clock::now();
    for (int i = n; i < n + 5; ++i) {
      step.add(data.inputs.row(i).transpose(), data.targets.row(i).transpose());
    }
    step.predict(query, mean, variance);
    add_times.push_back(std::chrono::duration<double>(Clock::now() - start).count());
    start = Clock::now();
    step.optimize_hyperparameters(rng);
    step.predict(query, mean, variance);
    warm_times.push_back(std::chrono::duration<double>(Clock::now() - start).count());
  }
  std::sort(add_times.begin(), add_times.end());
  std::sort(warm_times.begin(), warm_times.end());
  figures.add_seconds = add_times[2];
  figures.warm_seconds = warm_times[2];
  return figures;
}

}  // namespace
}  // namespace tendril::adapt

int main(int argc, char** argv) {
  using namespace tendril;
  using namespace tendril::adapt;
  bool quick = false, full = false, with_sklearn = true;
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    quick |= arg == "--quick";
    full |= arg == "--full";
    if (arg == "--no-sklearn") with_sklearn = false;
  }
  const std::vector<int> sizes =
      quick ? std::vector<int>{100, 500} : std::vector<int>{100, 250, 500, 1000, 2000};
  const std::vector<int> dims = quick ? std::vector<int>{3, 9} : std::vector<int>{3, 9, 12};
  std::vector<int> search_sizes = quick ? std::vector<int>{100} : std::vector<int>{100, 250, 500};
  if (full) search_sizes.push_back(1000);
  const std::vector<int> gprca_sizes = quick ? std::vector<int>{300} : std::vector<int>{300, 500};

  const auto directory =
      std::filesystem::temp_directory_path() /
      ("gp_bench_" + std::to_string(std::chrono::steady_clock::now().time_since_epoch().count()));
  std::filesystem::create_directories(directory);
  std::map<std::pair<int, int>, Data> datasets, multi_datasets;
  std::vector<Job> jobs;
  for (int d : dims) {
    for (int n : sizes) {
      datasets[{n, d}] = make_data(n, d, 1, 1000 * n + d);
      write_data(directory / ("data_" + std::to_string(n) + "_" + std::to_string(d) + ".bin"),
                 datasets[{n, d}]);
      const auto h = fixed_hyperparameters(d, 1.0);
      jobs.push_back({"fit_" + std::to_string(n) + "_" + std::to_string(d), "fit",
                      "squared_exponential", n, d, 0, h.length_scales[0], 1.0, 0.01});
      if (std::find(search_sizes.begin(), search_sizes.end(), n) != search_sizes.end()) {
        for (KernelType kernel : {KernelType::squared_exponential, KernelType::matern52}) {
          jobs.push_back({search_id(kernel, n, d), "optimize", kernel_type_name(kernel), n, d,
                          kRestarts, 1.0, 1.0, 0.01});
        }
      }
    }
  }
  for (int n : gprca_sizes) {
    const Data data = make_data(n + 5, kGprcaDim, kGprcaDim, 7 * n);
    multi_datasets[{n, kGprcaDim}] = data;
    write_data(directory / ("data_" + std::to_string(n) + "_9_multi.bin"),
               {data.inputs.topRows(n), data.targets.topRows(n), data.queries});
    jobs.push_back({"gprca_" + std::to_string(n), "multi", "squared_exponential", n, kGprcaDim, 0,
                    1.0, 1.0, 0.01});
    jobs.push_back({"gprca_shared_" + std::to_string(n), "multi_shared", "squared_exponential", n,
                    kGprcaDim, 0, 1.0, 1.0, 0.01});
  }
  const auto sklearn =
      with_sklearn ? run_sklearn(directory, jobs) : std::map<std::string, SklearnResult>{};
  const auto theirs = [&](const std::string& id) {
    const auto found = sklearn.find(id);
    return found == sklearn.end() ? SklearnResult{} : found->second;
  };

  std::printf("GP benchmark: tendril (Eigen, one thread) against scikit-learn %s\n",
              sklearn.empty() ? "(not run)" : "(OpenBLAS, one thread)");
  std::printf(
      "\nFit with fixed hyper-parameters (squared exponential), and predict %d points "
      "with variances\n",
      kQueries);
  std::printf("%5s %3s | %10s %10s %7s | %11s %11s %7s | %s\n", "n", "d", "fit ms", "sklearn",
              "ratio", "predict ms", "sklearn", "ratio", "max |Δmean|, |Δstd| / σ_y");
  for (int d : dims) {
    for (int n : sizes) {
      const Data& data = datasets[{n, d}];
      const double variance = data.target_variance();
      GaussianProcess gp(d, {}, fixed_hyperparameters(d, variance));
      const double fit = median_seconds([&] { gp.fit(data.inputs, data.targets.col(0)); });
      Eigen::VectorXd mean, noisy_variance;
      const double predict =
          median_seconds([&] { gp.predict(data.queries, mean, noisy_variance, true); });
      const std::string id = "fit_" + std::to_string(n) + "_" + std::to_string(d);
      const SklearnResult other = theirs(id);
      std::string agreement = "—";
      const auto prediction = read_doubles(directory / (id + ".prediction.bin"));
      if (prediction.size() == 2 * kQueries) {
        const Eigen::Map<const Eigen::VectorXd> other_mean(prediction.data(), kQueries);
        const Eigen::Map<const Eigen::VectorXd> other_std(prediction.data() + kQueries, kQueries);
        const double scale = std::sqrt(variance);
        char text[64];
        std::snprintf(text, sizeof text, "%.1e, %.1e",
                      (mean - other_mean).cwiseAbs().maxCoeff() / scale,
                      (noisy_variance.unaryExpr([](double v) { return std::sqrt(v); }) - other_std)
                              .cwiseAbs()
                              .maxCoeff() /
                          scale);
        agreement = text;
      }
      std::printf("%5d %3d | %10.3f %10.3f %7s | %11.3f %11.3f %7s | %s\n", n, d, 1e3 * fit,
                  1e3 * other.first_seconds, ratio(other.first_seconds, fit).c_str(), 1e3 * predict,
                  1e3 * other.second_seconds, ratio(other.second_seconds, predict).c_str(),
                  agreement.c_str());
    }
  }

  std::printf("\nFit with the maximum-likelihood search (1 + %d restarts)\n", kRestarts);
  std::printf("%20s %5s %3s | %10s %10s %7s | %14s %14s\n", "kernel", "n", "d", "fit ms", "sklearn",
              "ratio", "log p tendril", "log p sklearn");
  for (KernelType kernel : {KernelType::squared_exponential, KernelType::matern52}) {
    for (int d : dims) {
      for (int n : search_sizes) {
        const Data& data = datasets[{n, d}];
        const double variance = data.target_variance();
        GpOptions options;
        options.kernel = kernel;
        options.restarts = kRestarts;
        GaussianProcess gp(d, options, search_start(d, variance));
        Rng rng(1);
        const auto start = Clock::now();
        gp.fit(data.inputs, data.targets.col(0));
        const double log_likelihood = gp.optimize_hyperparameters(rng);
        const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
        const SklearnResult other = theirs(search_id(kernel, n, d));
        std::printf("%20s %5d %3d | %10.1f %10.1f %7s | %14.3f %14.3f\n",
                    kernel_type_name(kernel).c_str(), n, d, 1e3 * seconds,
                    1e3 * other.first_seconds, ratio(other.first_seconds, seconds).c_str(),
                    standardised(log_likelihood, n, variance), other.log_likelihood);
      }
    }
  }

  std::printf(
      "\nAdding the n-th point (d = 9, fixed hyper-parameters): O(n²) extension of the "
      "Cholesky factor against a refit\n");
  std::printf("%5s | %10s %10s %10s | %10s %10s | %12s\n", "n", "add ms", "refit ms", "ratio",
              "sklearn", "ratio", "window ms");
  for (int n : sizes) {
    if (!datasets.count({n, 9})) continue;
    const Data& data = datasets[{n, 9}];
    const auto hyper = fixed_hyperparameters(9, data.target_variance());
    GaussianProcess before(9, {}, hyper);
    before.reserve(n);  // the addition itself, not a reallocation of the storage
    before.fit(data.inputs.topRows(n - 1), data.targets.col(0).head(n - 1));
    const Eigen::VectorXd last = data.inputs.row(n - 1).transpose();
    const double target = data.targets(n - 1, 0);
    std::vector<double> times;
    for (int r = 0; r < 15; ++r) {
      GaussianProcess gp = before;
      const auto start = Clock::now();
      gp.add(last, target);
      times.push_back(std::chrono::duration<double>(Clock::now() - start).count());
    }
    std::sort(times.begin(), times.end());
    const double add = times[times.size() / 2];
    GaussianProcess refit_gp(9, {}, hyper);
    const double refit = median_seconds([&] { refit_gp.fit(data.inputs, data.targets.col(0)); });
    // A full window of n points: each addition also drops the oldest (a rank-one update).
    GpOptions windowed;
    windowed.window = n;
    GaussianProcess window(9, windowed, hyper);
    window.fit(data.inputs, data.targets.col(0));
    int next = 0;
    const double slide = median_seconds([&] {
      window.add(data.inputs.row(next % n).transpose(), data.targets(next % n, 0));
      ++next;
    });
    const SklearnResult other = theirs("fit_" + std::to_string(n) + "_9");
    std::printf("%5d | %10.3f %10.3f %10s | %10.3f %10s | %12.3f\n", n, 1e3 * add, 1e3 * refit,
                ratio(refit, add).c_str(), 1e3 * other.first_seconds,
                ratio(other.first_seconds, add).c_str(), 1e3 * slide);
  }

  std::printf(
      "\nGPRCA's compensator: 9-D action → 9-D error, 9 GPs over a full window of n "
      "points, retrained every 5 steps; budget 100 ms (10 Hz)\n");
  std::printf("%5s %-10s | %14s | %14s | %12s %12s %7s | %12s %12s\n", "n", "sharing",
              "5 added + pred", "warm search+p", "cold search+p", "sklearn", "ratio", "log p",
              "log p sklearn");
  for (int n : gprca_sizes) {
    for (HyperparameterSharing sharing :
         {HyperparameterSharing::per_output, HyperparameterSharing::shared}) {
      const bool shared = sharing == HyperparameterSharing::shared;
      const GprcaFigures ours = gprca_step(multi_datasets[{n, kGprcaDim}], n, sharing);
      const SklearnResult other = theirs((shared ? "gprca_shared_" : "gprca_") + std::to_string(n));
      std::printf("%5d %-10s | %11.2f ms | %11.1f ms | %9.1f ms %9.1f ms %7s | %12.3f %12.3f\n", n,
                  shared ? "shared" : "per output", 1e3 * ours.add_seconds, 1e3 * ours.warm_seconds,
                  1e3 * ours.cold_seconds, 1e3 * other.first_seconds,
                  ratio(other.first_seconds, ours.cold_seconds).c_str(), ours.cold_log_likelihood,
                  other.log_likelihood);
    }
  }
  std::filesystem::remove_all(directory);
  return 0;
}
