"""scikit-learn's side of bench/gp_bench: the same data, kernels, bounds and restarts.

Run by gp_bench as `/usr/bin/python3 gp_bench_sklearn.py <directory>`; reads
<directory>/jobs.txt, writes one result line per job to stdout and predictions to
<directory>/<id>.prediction.bin. Each job line is

    id kind kernel n d restarts length_scale constant noise

kind is `fit` (fixed hyper-parameters: fit, then predict the queries with standard deviations),
`optimize` (maximum-likelihood hyper-parameters from the given start and `restarts` random
ones), `multi` (one GP per output column, each optimised from the start, then one prediction)
or `multi_shared` (one GP for all output columns: one kernel, the likelihood summed over the
standardised columns). The data of a job is <directory>/data_<n>_<d>[_multi].bin: the n × d
inputs, then the n targets (n × d for `multi`), then 1000 × d queries, row-major float64.
The kernel is constant · (RBF or Matern ν = 5/2) + white noise with normalize_y=True, which
is tendril's GP with the prior mean at the targets' mean and the variances relative to the
targets' variance.
"""
import os
import sys
import time
import warnings

import numpy as np
from sklearn.gaussian_process import GaussianProcessRegressor
from sklearn.gaussian_process.kernels import RBF, ConstantKernel, Matern, WhiteKernel

QUERIES = 1000
LENGTH_SCALE_BOUNDS = (1e-3, 1e3)
CONSTANT_BOUNDS = (1e-3, 1e3)
NOISE_BOUNDS = (1e-8, 1.0)


def make_kernel(name, d, length_scale, constant, noise):
    scales = np.full(d, length_scale)
    if name == "squared_exponential":
        shape = RBF(scales, length_scale_bounds=LENGTH_SCALE_BOUNDS)
    else:
        shape = Matern(scales, length_scale_bounds=LENGTH_SCALE_BOUNDS, nu=2.5)
    return (ConstantKernel(constant, constant_value_bounds=CONSTANT_BOUNDS) * shape
            + WhiteKernel(noise, noise_level_bounds=NOISE_BOUNDS))


def load(directory, n, d, outputs):
    values = np.fromfile(os.path.join(directory, f"data_{n}_{d}{'_multi' if outputs > 1 else ''}.bin"))
    inputs = values[: n * d].reshape(n, d)
    targets = values[n * d : n * d + n * outputs].reshape(n, outputs)
    queries = values[n * d + n * outputs :].reshape(QUERIES, d)
    return inputs, targets, queries


def median_seconds(action, min_repeats=3, min_total=0.3):
    times = []
    while len(times) < min_repeats or sum(times) < min_total:
        start = time.perf_counter()
        action()
        times.append(time.perf_counter() - start)
    return float(np.median(times))


def main():
    warnings.filterwarnings("ignore")  # bound warnings: the same bounds bind tendril's search
    directory = sys.argv[1]
    with open(os.path.join(directory, "jobs.txt")) as jobs:
        for line in jobs:
            fields = line.split()
            if not fields:
                continue
            job, kind, name = fields[0], fields[1], fields[2]
            n, d, restarts = int(fields[3]), int(fields[4]), int(fields[5])
            length_scale, constant, noise = map(float, fields[6:9])
            kernel = make_kernel(name, d, length_scale, constant, noise)
            if kind == "fit":
                inputs, targets, queries = load(directory, n, d, 1)
                model = GaussianProcessRegressor(kernel, alpha=0.0, optimizer=None,
                                                 normalize_y=True)
                fit = median_seconds(lambda: model.fit(inputs, targets[:, 0]))
                predict = median_seconds(lambda: model.predict(queries, return_std=True))
                mean, std = model.predict(queries, return_std=True)
                np.concatenate([mean, std]).tofile(
                    os.path.join(directory, f"{job}.prediction.bin"))
                print(job, fit, predict, model.log_marginal_likelihood_value_, flush=True)
            elif kind == "optimize":
                inputs, targets, _ = load(directory, n, d, 1)
                model = GaussianProcessRegressor(kernel, alpha=0.0, normalize_y=True,
                                                 n_restarts_optimizer=restarts, random_state=0)
                start = time.perf_counter()
                model.fit(inputs, targets[:, 0])
                seconds = time.perf_counter() - start
                print(job, seconds, 0.0, model.log_marginal_likelihood_value_, flush=True)
            elif kind == "multi":
                inputs, targets, queries = load(directory, n, d, d)
                models = [GaussianProcessRegressor(kernel, alpha=0.0, normalize_y=True,
                                                   n_restarts_optimizer=restarts, random_state=k)
                          for k in range(targets.shape[1])]

                def retrain_and_predict():
                    for k, model in enumerate(models):
                        model.fit(inputs, targets[:, k])
                        model.predict(queries[:1], return_std=True)

                seconds = median_seconds(retrain_and_predict, min_repeats=1, min_total=0.0)
                lml = sum(model.log_marginal_likelihood_value_ for model in models)
                print(job, seconds, 0.0, lml, flush=True)
            elif kind == "multi_shared":
                inputs, targets, queries = load(directory, n, d, d)
                model = GaussianProcessRegressor(kernel, alpha=0.0, normalize_y=True,
                                                 n_restarts_optimizer=restarts, random_state=0)

                def retrain_and_predict():
                    model.fit(inputs, targets)
                    model.predict(queries[:1], return_std=True)

                seconds = median_seconds(retrain_and_predict, min_repeats=1, min_total=0.0)
                print(job, seconds, 0.0, model.log_marginal_likelihood_value_, flush=True)
            else:
                raise SystemExit(f"unknown job kind {kind}")


if __name__ == "__main__":
    main()
