// The program's commands: one table that the parser, `--help`, `tendril help` and the reference
// page (docs/cli.md, `tendril help --markdown`) all read. Commands whose layers are not built
// are left out.
#include "cli/command.hpp"
#include "commands.hpp"

namespace tendril::apps {

namespace {

OptionSpec output(const std::string& what) { return {"output", "PATH", what, 'o'}; }

OptionSpec seed_option(const std::string& what) { return {"seed", "S", what}; }

}  // namespace

std::vector<CommandSpec> command_table() {
  std::vector<CommandSpec> table;
#ifdef TENDRIL_WITH_RL
  table.push_back({
      .words = {"train"},
      .positionals = "EXPERIMENT.yaml",
      .min_positionals = 1,
      .max_positionals = 1,
      .summary = "Train a controller from an experiment file; write its run directory.",
      .description =
          "The run directory holds config.yaml (every key resolved, checksummed), machine.yaml "
          "(the build and CPU that made it), progress.csv (Stable-Baselines3's column names), a "
          "TensorBoard event file, eval.csv, checkpoints/ and model.policy; best_model.policy "
          "with eval.save_best. Ctrl-C (or SIGTERM) stops at the next iteration with a "
          "checkpoint; `tendril resume RUN` continues exactly.\n\n"
          "An experiment with a `safety:` section co-trains a safety agent beside the task "
          "agent (writes safety.critic; seed 001 ch. 6); one with a `constrained:` section "
          "trains a constrained baseline (Lagrangian relaxation or RSPO); both stop, pause "
          "and resume like any run, and end with their safety evaluation.",
      .options = {output("The run directory (default: the file's `output` -seed<N>-<time stamp>; "
                         "seeds of one experiment group together in report, plot and serve)."),
                  {"stop-at", "STEPS",
                   "Pause at the first checkpoint at or past STEPS (needs checkpoint_freq)."},
                  {"quiet", "", "No progress line."}},
      .takes_set = true,
      .set_help = "Change a key of the experiment, e.g. --set seed=3 --set algo.batch_size=64; a "
                  "misspelt key is an error naming it.",
      .examples =
          {"tendril train configs/ppo/pendulum.yaml --set seed=1",
           "tendril train configs/elastica/tracking3d_ppo.yaml -o runs/arm --stop-at 1000000"},
      .run = train_command,
  });
  table.push_back({
      .words = {"resume"},
      .positionals = "RUN",
      .min_positionals = 1,
      .max_positionals = 1,
      .summary = "Continue a paused or interrupted run from its newest intact checkpoint.",
      .description =
          "The resumed run computes what the uninterrupted run computes (off-policy runs: with "
          "save_replay_buffer: true); its config.yaml is used as saved. A model fit stopped by "
          "Ctrl-C or SIGTERM (its fit.ckpt) continues the same way, to the uninterrupted fit's "
          "model and logs. Safety co-training and constrained runs resume with their safety "
          "agent or cost critic.",
      .options = {{"stop-at", "STEPS", "Pause again at the first checkpoint at or past STEPS."},
                  {"quiet", "", "No progress line."}},
      .run = resume_command,
  });
  table.push_back({
      .words = {"run"},
      .positionals = "RUN|POLICY.policy",
      .min_positionals = 1,
      .max_positionals = 1,
      .summary = "Run a trained policy on an environment: returns, per-step means, traces, "
                 "episode files.",
      .description =
          "The policy of a run directory (model.policy; --best: best_model.policy; a paused run: "
          "its newest checkpoint) acts on the run's environment, as training evaluated it; a "
          "policy file acts on the environment --env names. Episode k resets with seed S + k, so "
          "any one episode can be run again alone (--seed S+k --episodes 1). Actions are the "
          "policy's mode unless --stochastic. Prints each episode (up to 20), the mean and sd "
          "of the return, the length and every info value at the episodes' ends (a success "
          "flag's mean is the success rate), and the mean per step of the reward and of every "
          "info value.",
      .options = {{"episodes", "N", "Run N whole episodes (default 10)."},
                  {"steps", "N", "Run N steps instead; the last episode may be cut short."},
                  seed_option("Episode k resets with S + k (default 0)."),
                  {"stochastic", "", "Sample actions instead of taking the policy's mode."},
                  {"best", "", "The run's best_model.policy (eval.save_best)."},
                  {"env", "ID", "Another environment (a policy file needs one)."},
                  {"trace", "FILE.csv",
                   "Every transition: observation, action, reward, next "
                   "observation, info and scene values (a new file)."},
                  {"record", "DIR",
                   "Every episode as an episode file in DIR, for `tendril serve` "
                   "and `tendril plot episode`."},
                  {"episodes-csv", "FILE.csv",
                   "One row per episode: seed, return, length, final "
                   "info values (a new file)."},
                  {"open-loop", "",
                   "Replay the actions the policy takes in one episode of the run's "
                   "own environment on this one (seed 002, Fig. 7)."},
                  {"filter", "RUN|FILE.critic",
                   "Act through the learned safety filter (seed 001 eq. 6.5) of a safety "
                   "run's safety.critic: the policy's action where the critic's value is at "
                   "above ε₂, the critic's safest action otherwise."},
                  {"epsilon", "E",
                   "The filter's threshold ε₂ (with --filter; `tendril safety "
                   "search` finds one)."}},
      .takes_set = true,
      .set_help = "Change the run's experiment for this, e.g. --set env.params.tip_mass=0.05: a "
                  "policy on conditions it was not trained on.",
      .examples = {"tendril run runs/ppo_pendulum-seed1-20261127-101500 --episodes 20",
                   "tendril run runs/limb_policy --set env.params.backend=bridge "
                   "--set env.params.bridge.port=/dev/ttyACM0 --filter runs/limb_safety "
                   "--epsilon 90",
                   "tendril run runs/ur5 --episodes 5 --trace ur5.csv",
                   "tendril run runs/arm --record runs/arm/episodes --episodes 2"},
      .run = run_command,
  });
#endif
#ifdef TENDRIL_WITH_SWEEPS
  table.push_back({
      .words = {"sweep", "run"},
      .positionals = "SWEEP.yaml",
      .min_positionals = 1,
      .max_positionals = 1,
      .summary = "Train the runs of a sweep (a grid of overrides of one experiment).",
      .description =
          "Runs go to <output>/<run>; finished runs are kept, interrupted ones resumed, runs "
          "another process holds left to it, so the same command continues a sweep. Under "
          "mpirun (or srun) each rank trains its share. The process that finishes the last run "
          "writes <output>/summary/ (docs/sweeps.md).",
      .options = {{"only", "I", "Train only run I (see `tendril sweep list`)."},
                  {"rank", "R", "This process's share R of --ranks N (else from MPI/Slurm)."},
                  {"ranks", "N", "The number of processes sharing the runs."},
                  {"quiet", "", "No progress lines."},
                  {"no-figures", "", "Write the summary without figures."}},
      .examples = {"tendril sweep run configs/ur5/sweeps/ppo_base_seeds.yaml",
                   "mpirun --allow-run-as-root -n 2 --bind-to none tendril sweep run "
                   "configs/ur5/sweeps/ppo_base_seeds.yaml"},
      .run = sweep_run_command,
  });
  table.push_back({
      .words = {"sweep", "list"},
      .positionals = "SWEEP.yaml",
      .min_positionals = 1,
      .max_positionals = 1,
      .summary = "List a sweep's runs (index and directory).",
      .options = {{"only", "I", "Only run I."},
                  {"rank", "R", "Only the share of rank R of --ranks N."},
                  {"ranks", "N", "The number of processes sharing the runs."}},
      .run = sweep_list_command,
  });
  table.push_back({
      .words = {"sweep", "summarize"},
      .positionals = "SWEEP.yaml",
      .min_positionals = 1,
      .max_positionals = 1,
      .summary = "Write <output>/summary/ from a sweep's runs as they are, without training.",
      .options = {{"no-figures", "", "Tables only."}},
      .run = sweep_summarize_command,
  });
  table.push_back({
      .words = {"sweep", "slurm"},
      .positionals = "SWEEP.yaml",
      .min_positionals = 1,
      .max_positionals = 1,
      .summary = "Write a Slurm job-array script whose tasks share a sweep's runs.",
      .options = {{"tasks", "K", "Array tasks (default: one per run)."},
                  {"max-running", "M", "At most M tasks at once."},
                  {"time", "T", "Wall-time limit per task (default 24:00:00)."},
                  {"cpus-per-task", "C", "CPUs per task."},
                  {"mem", "M", "Memory per task."},
                  {"partition", "P", "Slurm partition."},
                  {"account", "A", "Slurm account."},
                  {"job-name", "N", "Job name."},
                  {"stop-before", "S",
                   "Seconds before the limit at which a task stops "
                   "politely (SIGTERM, a checkpoint)."},
                  output("The script (default <output>/slurm/sweep.sbatch).")},
      .run = sweep_slurm_command,
  });
  table.push_back({
      .words = {"report"},
      .positionals = "RUN|DIR ...",
      .min_positionals = 1,
      .max_positionals = -1,
      .summary = "A Markdown table of runs: training means, final evaluations, training time, "
                 "per run and over seeds.",
      .description = "Runs whose names differ only by a seed token (seed3, _s3) are grouped; "
                     "the table gives mean ± std over them (docs/sweeps.md).",
      .options = {{"at", "STEPS,...", "Also the training mean at each of these steps."}},
      .run = report_command,
  });
#endif
#ifdef TENDRIL_WITH_DATA
  const std::string limb_file =
      "An SMA limb file names its protocol in `task:`, which must match the command.";
  table.push_back({
      .words = {"data", "collect"},
      .positionals = "CONFIG.yaml",
      .min_positionals = 1,
      .max_positionals = 1,
      .summary = "Record a robot's data set (SMA limb: explore or babble; pneumatic arm: the "
                 "saturating pressure signal; tendon arm: random held tensions).",
      .description = limb_file + " A data set is a CSV file with a schema and a CRC-32C line "
                                 "(docs/data_sets.md).",
      .options = {output(
          "The data set (pneumatic and tendon arm; the SMA limb's come from its file).")},
      .takes_set = true,
      .set_help = "Change a key of the file, e.g. --set output=data/mine.csv.",
      .examples = {"tendril data collect configs/sma_limb/explore_stiff.yaml "
                   "--set output=my_stiff.csv --set prepare.output=my_stiff_prepared.csv"},
      .run = data_collect_command,
  });
  table.push_back({
      .words = {"data", "calibrate"},
      .positionals = "CONFIG.yaml",
      .min_positionals = 1,
      .max_positionals = 1,
      .summary = "Calibrate the SMA limb: its PWM table and its sensor's zero offsets.",
      .description = limb_file,
      .takes_set = true,
      .set_help = "Change a key of the file, e.g. --set output=my_calibration.yaml.",
      .run = data_calibrate_command,
  });
  table.push_back({
      .words = {"data", "replay"},
      .positionals = "CONFIG.yaml",
      .min_positionals = 1,
      .max_positionals = 1,
      .summary = "Replay fixed inputs on a robot (SMA limb after cool-downs; pneumatic arm in "
                 "repeated trials per damage scenario).",
      .description = limb_file,
      .options = {output("The output directory (pneumatic arm).")},
      .takes_set = true,
      .set_help = "Change a key of the file.",
      .run = data_replay_command,
  });
  table.push_back({
      .words = {"data", "coverage"},
      .positionals = "CONFIG.yaml",
      .min_positionals = 1,
      .max_positionals = 1,
      .summary = "Compare how exploration and babbling cover the SMA limb's bend angles.",
      .description = limb_file,
      .takes_set = true,
      .set_help = "Change a key of the file.",
      .run = data_coverage_command,
  });
  table.push_back({
      .words = {"data", "open-loop"},
      .positionals = "CONFIG.yaml",
      .min_positionals = 1,
      .max_positionals = 1,
      .summary = "Record the SMA limb's response to the open-loop test inputs (sine, square, "
                 "sawtooth).",
      .description = limb_file,
      .takes_set = true,
      .set_help = "Change a key of the file.",
      .run = data_open_loop_command,
  });
#endif
#ifdef TENDRIL_WITH_DYNAMICS
  table.push_back({
      .words = {"data", "prepare"},
      .min_positionals = 0,
      .max_positionals = 0,
      .summary = "Prepare the pneumatic arm's recordings for `tendril model fit`.",
      .description = "Writes time_s, the tips x1 … z3 [mm], the commanded pressures p1 … p9 "
                     "[bar] and the split of each row.",
      .options = {{"train", "FILE", "The recording for training."},
                  {"test", "FILE", "The recording for testing."},
                  output("The prepared data set.")},
      .run = data_prepare_command,
  });
  table.push_back({
      .words = {"model", "fit"},
      .positionals = "FIT.yaml",
      .min_positionals = 1,
      .max_positionals = 1,
      .summary = "Fit a learned dynamics model to a prepared data set; write its run directory.",
      .description = "The run directory holds config.yaml (every key resolved, checksummed), "
                     "machine.yaml, progress.csv (train/loss, "
                     "train/val_loss per epoch), TensorBoard events, model.tdm and "
                     "evaluation.csv (one-step and rollout RMSE on the test split). Ctrl-C (or "
                     "SIGTERM) stops at the end of the epoch with a checkpoint; `tendril resume "
                     "RUN` continues exactly.",
      .options = {output("The run directory (default: the file's `output` plus a time stamp)."),
                  {"quiet", "", "No progress line."}},
      .takes_set = true,
      .set_help = "Change a key of the file, e.g. --set training.epochs=10 --set seed=2.",
      .examples = {"tendril model fit configs/dynamics/sma_stiff_seq2seq_attention.yaml"},
      .run = model_fit_command,
  });
  table.push_back({
      .words = {"model", "eval"},
      .positionals = "RUN|MODEL.tdm DATA.csv",
      .min_positionals = 2,
      .max_positionals = 2,
      .summary = "One-step and rollout RMSE of a model on a prepared data set.",
      .options = {{"split", "test|train", "Which rows (default test)."},
                  {"horizons", "S,...", "Rollout horizons in seconds (default 60,1800)."},
                  {"max-gap", "S",
                   "Longest time gap inside one segment (default: from the "
                   "data)."},
                  output("The errors as CSV (a new file)."),
                  {"open-loop-dir", "DIR",
                   "The model's open-loop response to the sine, square "
                   "and sawtooth test inputs, one CSV each."},
                  {"baselines", "",
                   "Also the \"predict no change\" baseline on the same points (rows "
                   "persistence_*), and the one-step errors of both within 3 readings of an "
                   "input change and under steady input (*_input_change, *_steady_input)."}},
      .run = model_eval_command,
  });
#endif
#ifdef TENDRIL_WITH_SAFETY
  table.push_back({
      .words = {"safety", "eval"},
      .positionals = "RUN",
      .min_positionals = 1,
      .max_positionals = 1,
      .summary = "Return and safety rate of a run's policy with and without the safety filter.",
      .options = {{"epsilon", "E,...", "The filter's threshold ε₂ (default the run's)."},
                  {"episodes", "N", "Episodes per threshold (default the run's, else 100)."},
                  seed_option("Episode k resets with S + k (default the run's seed)."),
                  {"task", "RUN|random", "Another task policy under this run's filter."},
                  {"csv", "FILE", "One row per threshold."},
                  {"trajectory", "FILE", "Every step of the first threshold's episodes."}},
      .run = safety_eval_command,
  });
  table.push_back({
      .words = {"safety", "search"},
      .positionals = "RUN",
      .min_positionals = 1,
      .max_positionals = 1,
      .summary = "Search the filter's threshold ε₂ by gradient descent on the safety value "
                 "(seed 001 Algorithm 3).",
      .options = {{"restarts", "N", "Restarts (default 20)."},
                  {"step-size", "A", "Gradient step in normalised state units."},
                  {"tolerance", "D", "Convergence tolerance."},
                  seed_option("Of the restarts (default 0)."),
                  {"csv", "FILE", "One row per restart."},
                  {"final-value", "", "Take each restart's final value, not the survivor's."}},
      .run = safety_search_command,
  });
  table.push_back({
      .words = {"safety", "map"},
      .positionals = "RUN",
      .min_positionals = 1,
      .max_positionals = 1,
      .summary = "The learned safety value on a grid of two state coordinates (CSV).",
      .options = {output("The map (CSV)."),
                  {"resolution", "N", "Points per axis (default 101)."},
                  {"extent", "X", "Half-width of the grid."},
                  {"axes", "I,J", "The two state coordinates."},
                  {"fixed", "V,...", "The other coordinates' values."},
                  {"epsilon", "E,...",
                   "Report the share of learned-safe states outside the "
                   "analytic safe set at these thresholds."}},
      .run = safety_map_command,
  });
  table.push_back({
      .words = {"safety", "diamond"},
      .positionals = "RUN",
      .min_positionals = 1,
      .max_positionals = 1,
      .summary = "The SMA limb under the diamond throttle sequence through the safety filter "
                 "(seed 001 §6.5): time to the first violation.",
      .description =
          "The limb runs on the calibration the critic's learned model was fitted with (its data "
          "set's header names it); a --calibration with another PWM table or other zero offsets "
          "is refused. --set env.params.KEY=VALUE sets the robot's other parameters, e.g. "
          "--set env.params.backend=bridge (docs/hardware.md).",
      .options = {{"epsilon", "E,...", "Thresholds ε₂."},
                  {"trials", "N", "Trials per threshold."},
                  seed_option("Trial k resets with S + k."),
                  {"limb", "stiff|soft", "The limb (default stiff)."},
                  {"calibration", "FILE|none",
                   "The limb's calibration; default the critic's model's (required when the "
                   "model does not name one)."},
                  {"csv", "FILE", "One row per trial."},
                  {"trajectories", "FILE", "Every step of every trial."}},
      .takes_set = true,
      .set_help = "Set a parameter of the robot (SmaLimb/Robot-v0), e.g. "
                  "--set env.params.backend=bridge.",
      .run = safety_diamond_command,
  });
#endif
#ifdef TENDRIL_WITH_ADAPT
  table.push_back({
      .words = {"adapt"},
      .positionals = "ADAPT.yaml",
      .min_positionals = 1,
      .max_positionals = 1,
      .summary = "Adapt trained policies online on the pneumatic arm (seed 002: BOAC or GPRCA).",
      .description =
          "Every goal × damage scenario × seed of the file, with per-trial logs and summary.csv "
          "(Table II's parameters P1–P5), beside config.yaml (resolved, checksummed) and "
          "machine.yaml. Ctrl-C (or SIGTERM) stops after the current "
          "adaptation; the same command continues, keeping the adaptations written (each is "
          "seeded on its own, so the result is the uninterrupted one's). An existing output of "
          "another configuration, or that is no adaptation's, is refused: nothing is overwritten.",
      .options = {output("The output directory (default the file's `output`).")},
      .takes_set = true,
      .set_help = "Change a key of the file, e.g. --set seeds=[0].",
      .run = adapt_command,
  });
#endif
#ifdef TENDRIL_WITH_DATA
  table.push_back({
      .words = {"track"},
      .positionals = "[PATTERN|all]",
      .min_positionals = 0,
      .max_positionals = 1,
      .summary = "Track reference paths in bend-angle space on the SMA limb twin (waypoints "
                 "and PID, or a trained policy); print the tracking RMSE.",
      .description =
          "The limb runs on the calibration its controller was made for: with --policy, the one "
          "the policy's learned model was fitted with (its data set's header names it); a "
          "--calibration with another PWM table or other zero offsets is refused. PID needs "
          "--calibration. --set env.params.KEY=VALUE sets the robot's other parameters, e.g. "
          "--set env.params.backend=bridge --set env.params.bridge.port=/dev/ttyACM0 for a limb "
          "over the host bridge (docs/hardware.md).",
      .options = {{"calibration", "FILE|none",
                   "The limb's calibration (`tendril data calibrate`); default the policy's "
                   "model's. `none`: the nominal table on raw readings (refused for a policy "
                   "made on calibrated data)."},
                  {"limb", "stiff|soft", "The limb (default stiff)."},
                  {"tip-mass", "KG", "A mass on the tip (default 0)."},
                  {"push", "N", "Shove the tip at 1/4 and 3/4 of the path (N)."},
                  {"steps", "N", "At most N steps per path (default 3000)."},
                  seed_option("The twin's seed (default 0)."),
                  output("Every step as CSV (a new file)."),
                  {"policy", "RUN",
                   "A policy trained in SmaLimb/LearnedReach-v0 instead of "
                   "PID."},
                  {"best", "", "Its best_model.policy."},
                  {"stochastic", "", "Sample its actions."}},
      .takes_set = true,
      .set_help = "Set a parameter of the robot (SmaLimb/Robot-v0), e.g. "
                  "--set env.params.backend=bridge.",
      .examples = {"tendril track circle --calibration configs/sma_limb/calibration_stiff.yaml",
                   "tendril track all --policy runs/rl/lk_encoder -o paths.csv"},
      .run = track_command,
  });
#endif
  table.push_back({
      .words = {"simulate"},
      .positionals = "SCENE.yaml",
      .min_positionals = 1,
      .max_positionals = 1,
      .summary = "Simulate a Cosserat-rod arm under a spline muscle couple; write tip.csv and "
                 "nodes.csv.",
      .options = {output("The output directory (default: the file's `output` plus a time "
                         "stamp)."),
                  {"overwrite", "", "Replace the files of a non-empty output directory."}},
      .takes_set = true,
      .set_help = "Change a key of the file, e.g. --set duration=2.",
      .examples = {"tendril simulate configs/rod/elastica_arm_bend.yaml"},
      .run = simulate_command,
  });
#ifdef TENDRIL_WITH_DASHBOARD
  table.push_back({
      .words = {"serve"},
      .positionals = "DIR",
      .min_positionals = 1,
      .max_positionals = 1,
      .summary = "The dashboard of the runs under DIR: curves that follow training, seeds side "
                 "by side, configs, 3D replays.",
      .description = "Read-only; binds to 127.0.0.1 unless --host says otherwise.",
      .options = {{"port", "P", "The port (default 8050; 0 picks a free one)."},
                  {"host", "H", "The address to listen on (default 127.0.0.1)."},
                  {"assets", "DIR", "The page's files (default: the built page)."}},
      .examples = {"tendril serve runs"},
      .run = serve_command,
  });
#endif
#ifdef TENDRIL_WITH_RL
  table.push_back({
      .words = {"export"},
      .positionals = "RUN|POLICY.policy",
      .min_positionals = 1,
      .max_positionals = 1,
      .summary = "A trained policy for other runtimes: a dependency-free C header, an ONNX model.",
      .description =
          "Both compute the policy's deterministic action from a raw observation: its "
          "observation normalization, its layers, then the action's squash and scaling into the "
          "action space (or the argmax of a discrete policy), as `tendril run` computes it. The C "
          "header is C89 with <math.h> only: float weights (in flash under avr-gcc) and "
          "NAME_act(observation, action); it compiles for the SMA limb's ATmega328P. The ONNX "
          "model (opset 13, checked with onnx.checker) is written by the Python package "
          "(python3-onnx). Policies of PPO, TRPO, SAC, TD3, DDPG and DQN with MLP networks; "
          "existing files are never replaced (docs/export.md).",
      .options = {{"c", "FILE.h", "Write the policy as a C header."},
                  {"name", "NAME", "The C header's identifier prefix (default policy)."},
                  {"onnx", "FILE.onnx", "Write the policy as an ONNX model."},
                  {"best", "", "The run's best_model.policy (eval.save_best)."}},
      .examples = {"tendril export runs/limb --c limb_policy.h --name limb",
                   "tendril export runs/arm --onnx arm.onnx"},
      .run = export_command,
  });
#endif
  table.push_back({
      .words = {"plot"},
      .positionals = "curves|episode|csv|map ...",
      .min_positionals = 0,
      .max_positionals = -1,
      .summary = "Figures (PNG, SVG, PDF) of runs, sweeps, CSV files and recorded episodes "
                 "(matplotlib); videos of recorded episodes.",
      .description = "`tendril plot <kind> --help` lists each kind's options (docs/plotting.md). "
                     "`plot episode EPISODE --video -o FILE.mp4` (or .webm, .gif) writes a "
                     "video of a recorded episode instead, drawn by tendril's software "
                     "rasterizer and encoded by ffmpeg.",
      .examples = {"tendril plot curves runs/sweeps/my_sweep -o curves.png",
                   "tendril plot episode runs/arm/episodes/episode_0000.tep --video -o arm.mp4"},
      .passthrough = true,
      .run = plot_command,
  });
#ifdef TENDRIL_WITH_ENVS
  table.push_back({
      .words = {"robot", "emulate"},
      .positionals = "limb|arm",
      .min_positionals = 1,
      .max_positionals = 1,
      .summary = "Emulate a robot's hardware on this machine: the SMA limb's firmware in simavr "
                 "on a pseudo-terminal, or the pneumatic arm's lab on UDP (docs/hardware.md).",
      .description = "Everything tendril does with a robot (`backend: bridge`) then runs against "
                     "it as against the real one. Ctrl-C stops it.",
      .options = {{"link", "PATH", "Limb: the pseudo-terminal's link (default /tmp/tendril-limb)."},
                  {"limb", "stiff|soft", "Limb: which twin (default stiff)."},
                  {"firmware", "ELF", "Limb: the firmware image (default: the one built)."},
                  seed_option("Limb: the twin's seed (default 0)."),
                  {"command-port", "P", "Arm: the regulators' UDP port (default 51000)."},
                  {"mocap-port", "P", "Arm: where the motion capture streams (default 51001)."},
                  {"pace", "realtime|lockstep",
                   "Real time (default), or robot time paused while "
                   "the host answers (tests)."}},
      .takes_set = true,
      .set_help = "Arm: a parameter of PneumaticArm/Robot-v0's twin.",
      .examples = {"tendril robot emulate limb --link /tmp/limb"},
      .run = robot_emulate_command,
  });
  table.push_back({
      .words = {"robot", "check"},
      .positionals = "limb|arm",
      .min_positionals = 1,
      .max_positionals = 1,
      .summary = "Check a robot link: handshake, round-trip latency, sensor and control rates, "
                 "limits.",
      .options = {{"port", "DEVICE", "Limb: the serial device (or an emulator's link)."},
                  {"baud", "B", "Limb: the baud rate (default 115200)."},
                  {"udp-port", "P", "Arm: the regulators' UDP port (default 51000)."},
                  {"mocap-port", "P", "Arm: the motion capture's port (default 51001)."},
                  {"pings", "N", "Round trips to time (default 50)."},
                  {"steps", "N", "Steps of zero command to time (default 100)."}},
      .examples = {"tendril robot check limb --port /tmp/limb"},
      .run = robot_check_command,
  });
  table.push_back({
      .words = {"list", "envs"},
      .positionals = "[ID ...]",
      .min_positionals = 0,
      .max_positionals = -1,
      .summary = "The registered environment ids, their time limits and what they are.",
      .description = "With --describe, each environment as its default parameters make it: "
                     "observation and action spaces with the meaning and unit of every entry, "
                     "how it rewards and when its episodes end, the info values a step reports, "
                     "and the parameters it reads with their defaults (or the parameters it "
                     "needs). docs/envs.md is --markdown's output.",
      .options = {{"describe", "",
                   "Spaces with their entries and units, reward, episode end, info values and "
                   "parameters of each environment."},
                  {"markdown", "", "The reference page docs/envs.md."}},
      .examples = {"tendril list envs --describe Elastica/Tracking3D-v0"},
      .run = list_envs_command,
  });
  table.push_back({
      .words = {"list", "wrappers"},
      .summary = "The wrappers an experiment's env.wrappers may name.",
      .run = list_wrappers_command,
  });
#endif
#ifdef TENDRIL_WITH_RL
  table.push_back({
      .words = {"list", "algorithms"},
      .summary = "The algorithms an experiment's `algorithm` may name.",
      .run = list_algorithms_command,
  });
#endif
  return table;
}

}  // namespace tendril::apps
