// tendril — simulate soft robots, train and evaluate controllers for them.
#include <csignal>
#include <cstdio>
#include <exception>
#include <new>
#include <string>
#include <vector>

#include "commands.hpp"
#include "tendril/core/error.hpp"
#ifdef TENDRIL_WITH_RL
#include "tendril/nn/threads.hpp"
#endif
#ifdef TENDRIL_WITH_DYNAMICS
#include "tendril/dynamics/env_model_loader.hpp"
#include "tendril/dynamics/policy_heads.hpp"
#endif

namespace {

constexpr const char* kUsage = R"(usage: tendril <command> [arguments]

commands:
  simulate <experiment.yaml> [--set key=value ...] [--out DIR]
      Simulate a Cosserat-rod arm under a spline muscle couple; write its tip trajectory
      (tip.csv) and final shape (nodes.csv) to DIR, and print what happened.
  train <experiment.yaml> [--set key=value ...] [--out DIR] [--stop-at STEPS] [--quiet]
  train --resume <run-dir>
      Train a controller; write the run directory (config, progress.csv, TensorBoard events,
      eval.csv, checkpoints/, model.policy). --stop-at pauses at the first checkpoint past STEPS.
  eval <run-dir> [--episodes N] [--deterministic] [--seed S] [--best] [--open-loop]
       [--out FILE.csv] [--set key=value ...]
      Evaluate a run's policy (model.policy, else its newest checkpoint; --best:
      best_model.policy): returns, lengths and every info value at the episodes' ends (mean
      and sd: a success flag's mean is the success rate); --set changes the run's experiment
      for this (e.g. env.id, env.params: a policy on conditions it was not trained on);
      --open-loop replays the actions of one episode in the run's own environment instead;
      --out writes one row per episode (return, length, final info values) to a new CSV.
  rollout <run-dir> [--episodes N | --steps N] [--out FILE.csv] [--seed S] [--best]
          [--deterministic|--stochastic] [--set key=value ...]
      Run a run's policy for N episodes (reset seeds S, S+1, ...) or N steps; print the mean
      per step of the reward and of every info value; --out writes every transition
      (observation, action, reward, next observation, info and scene values) to a new CSV file;
      --set changes the run's experiment for this (e.g. env.params).
  sweep <sweep.yaml> [--list] [--only I] [--rank R --ranks N] [--quiet] [--no-figures]
      Train the runs of a sweep file (a grid of overrides of one experiment) one after the
      other into <output>/<run>; finished runs are kept, interrupted ones resumed, runs another
      process holds left to it. Under mpirun (or srun) each rank trains its share. When every
      run has finished, writes <output>/summary/ (mean and spread over seeds: tables, curves,
      figures).
  sweep <sweep.yaml> --aggregate-only [--no-figures]
      Write <output>/summary/ from the runs as they are, without training.
  sweep <sweep.yaml> --slurm [--tasks K] [--max-running M] [--time T] [--cpus-per-task C]
        [--mem M] [--partition P] [--account A] [--job-name N] [--stop-before S] [--out FILE]
      Write a Slurm job-array script (<output>/slurm/sweep.sbatch) whose tasks share the runs.
  summarize <run-dir|dir of runs> ... [--at STEPS,STEPS...]
      A Markdown table of runs outside a sweep: training mean at each step of --at and at the
      end, final evaluation, training time; per run and as mean ± std over runs whose names
      differ only by seed (docs/sweeps.md).
  collect-pneumatic <collect.yaml> [--set key=value ...] [--out FILE]
      Record the pneumatic arm's data set (seed 002: 10 min at 10 Hz under a dynamically
      saturating pressure signal) from PneumaticArm/Robot-v0 into a CSV file.
  replay-pneumatic <replay.yaml> [--set key=value ...] [--out DIR]
      Replay one pressure trajectory on the pneumatic arm in repeated trials per damage
      scenario; write each module's mean distance from the base trial (replay_gap.csv).
  prepare-pneumatic --train FILE [--test FILE] --out FILE
      The pneumatic arm's recordings (collect-pneumatic) as a prepared data set for
      `dynamics fit`: time_s, tips x1 … z3 [mm], commanded pressures p1 … p9 [bar], split.
  adapt <adapt.yaml> [--set key=value ...] [--out DIR]
      Adapt trained policies online on the pneumatic arm (seed 002: BOAC or GPRCA) in every
      goal x damage scenario x seed of the file; per-trial logs and summary.csv (Table II).
  record <run-dir> [--episodes N] [--best] [--out DIR] [--seed S] [--deterministic|--stochastic]
      Record episodes of a run's model (as eval picks it) into <run-dir>/episodes/ (or DIR):
      the scene of every step, actions, rewards, info (docs/episode_format.md).
  export <run-dir|file.policy> [--c FILE.h [--name NAME]] [--onnx FILE.onnx] [--best]
      A run's policy for other runtimes: a dependency-free C header (float weights and
      NAME_act(observation, action), normalization and action scaling included; compiles for
      an ATmega328P) and/or an ONNX model; both give the policy's deterministic action.
  serve <dir> [--port P] [--host H]
      The dashboard of the runs under DIR at http://127.0.0.1:8050/: learning curves that
      follow training, seeds side by side, configs, 3D replays of recorded episodes.
      Read-only; binds to 127.0.0.1 unless --host says otherwise.
  plot curves|episode|csv ... --out FILE.png|.svg|.pdf
      Figures without a browser (matplotlib): learning curves of runs and sweeps with mean and
      spread over seeds, snapshots of recorded episodes, any columns of CSV files.
      `tendril plot <kind> --help` lists each kind's options.
  collect <config.yaml> [--set key=value ...]
      Calibrate the SMA limb, collect its data sets (written beside their prepared form),
      replay open-loop throttles after cool-downs, compare exploration with babbling, or
      record the limb's response to the open-loop test inputs.
  track [circle|square|spiral|sml|all] [--limb stiff|soft] [--tip-mass KG] [--push N]
        [--steps N] [--seed S] [--out FILE.csv] [--policy RUN [--best] [--stochastic]]
      Track reference paths in bend-angle space on the SMA limb twin with the 10° waypoint
      follower and the PID baseline, or a policy trained in SmaLimb/LearnedReach-v0 (its run
      directory); print the tracking RMSE per path (--out: every step).
  dynamics fit <fit.yaml> [--set key=value ...] [--out DIR] [--quiet]
      Fit a learned dynamics model to a prepared data set; write the run directory (config,
      progress.csv, TensorBoard events, model.tdm, evaluation.csv).
  dynamics eval <run-dir|model.tdm> <data.csv> [--split test|train] [--horizons 60,1800]
                [--out FILE.csv] [--open-loop DIR]
      One-step and rollout RMSE of a model on a data set; open-loop sine/square/sawtooth runs.
  safety train <experiment.yaml> [--set key=value ...] [--out DIR]
  safety eval <run-dir> [--epsilon E] [--episodes N] [--seed S]
      Train a task agent with a safety agent co-trained from its rollouts (the experiment's
      `safety:` section; writes model.policy and safety.critic); evaluate return and safety
      rate of the task policy with and without the safety filter at threshold E.
  list-envs
      The registered environment ids.
  help
      Show this text.
)";

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "help" || args[0] == "--help" || args[0] == "-h") {
    std::fputs(kUsage, args.empty() ? stderr : stdout);
    return args.empty() ? 2 : 0;
  }
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  // A closed output pipe (`tendril train ... | head`) or a file-size limit makes writes fail
  // with an error that names the file, instead of ending the process mid-run.
  std::signal(SIGPIPE, SIG_IGN);
  std::signal(SIGXFSZ, SIG_IGN);
  try {
#ifdef TENDRIL_WITH_RL
    // One BLAS thread unless an algorithm scopes more: the other core steps environments.
    tendril::nn::configure_numerics(1);
#endif
#ifdef TENDRIL_WITH_DYNAMICS
    // Environments around learned models open them from their `model` parameter.
    tendril::dynamics::install_model_loader();
    // Policies with a learned-model head (seed 001 ch. 5) are trained and loaded.
    tendril::dynamics::install_policy_heads();
#endif
    if (args[0] == "simulate") return tendril::apps::simulate_command(rest);
    if (args[0] == "plot") return tendril::apps::plot_command(rest);
#ifdef TENDRIL_WITH_ENVS
    if (args[0] == "list-envs") return tendril::apps::list_envs_command(rest);
    if (args[0] == "collect-pneumatic") return tendril::apps::pneumatic_collect_command(rest);
    if (args[0] == "replay-pneumatic") return tendril::apps::pneumatic_replay_command(rest);
#endif
#ifdef TENDRIL_WITH_DASHBOARD
    if (args[0] == "serve") return tendril::apps::serve_command(rest);
#endif
#ifdef TENDRIL_WITH_DATA
    if (args[0] == "collect") return tendril::apps::collect_command(rest);
    if (args[0] == "track") return tendril::apps::track_command(rest);
#endif
#ifdef TENDRIL_WITH_RL
    if (args[0] == "train") return tendril::apps::train_command(rest);
    if (args[0] == "eval") return tendril::apps::eval_command(rest);
    if (args[0] == "sweep") return tendril::apps::sweep_command(rest);
    if (args[0] == "summarize") return tendril::apps::summarize_command(rest);
    if (args[0] == "record") return tendril::apps::record_command(rest);
    if (args[0] == "rollout") return tendril::apps::rollout_command(rest);
    if (args[0] == "export") return tendril::apps::export_command(rest);
#endif
#ifdef TENDRIL_WITH_ADAPT
    if (args[0] == "adapt") return tendril::apps::adapt_command(rest);
#endif
#ifdef TENDRIL_WITH_SAFETY
    if (args[0] == "safety") return tendril::apps::safety_command(rest);
#endif
#ifdef TENDRIL_WITH_DYNAMICS
    if (args[0] == "dynamics") return tendril::apps::dynamics_command(rest);
    if (args[0] == "prepare-pneumatic") return tendril::apps::pneumatic_prepare_command(rest);
#endif
    std::fprintf(stderr, "tendril: unknown command '%s'\n\n%s", args[0].c_str(), kUsage);
    return 2;
  } catch (const tendril::Error& e) {
    std::fprintf(stderr, "tendril %s: error: %s\n", args[0].c_str(), e.what());
    return 1;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "tendril %s: error: out of memory\n", args[0].c_str());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tendril %s: unexpected error: %s\n", args[0].c_str(), e.what());
    return 1;
  }
}
