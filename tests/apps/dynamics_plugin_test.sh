#!/usr/bin/env bash
# LibTorch only for the commands that need it: the program does not link it; the dynamics
# plugin beside it (LibTorch, the learned models) is loaded by the model commands, learned-model
# environments and learned-model policy heads, and by nothing else; the plugin uses the
# program's layers (one environment registry, one model loader, one table of head kinds); a
# missing plugin is an error naming the file, before anything is written.
#   dynamics_plugin_test.sh <source dir> <tendril program> <scratch dir>
set -u
source=$1 tendril=$2 scratch=$3
plugin=$(dirname "$tendril")/libtendril_dynamics_plugin.so
rm -rf "$scratch" && mkdir -p "$scratch" && cd "$scratch" || exit 1
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
# Commands run from the source tree (the configurations' data paths); their files land here.
log=$scratch/log loaded=$scratch/loaded.txt

# The libraries a command's process opened (the dynamic loader's record, dlopen included), in
# loaded.txt; its output in log. Returns the command's status.
run_recorded() {
  rm -f "$scratch"/ld.*
  LD_DEBUG=files LD_DEBUG_OUTPUT=$scratch/ld "$@" >"$log" 2>&1
  local rc=$?
  cat "$scratch"/ld.* 2>/dev/null | grep -o 'file=[^ ]*' | sort -u >"$loaded"
  rm -f "$scratch"/ld.*
  return $rc
}
without_torch() {  # <what> <command...>
  local what=$1
  shift
  run_recorded "$@" || fail "$what: rc=$?: $(tail -2 "$log")"
  grep -q "libtendril_dynamics_plugin\|libtorch" "$loaded" && fail "$what loaded LibTorch"
  grep -q "libstdc++" "$loaded" || fail "$what: no record of the libraries it opened"
}
with_torch() {  # <what> <command...>: the command succeeds and loaded the plugin and LibTorch
  local what=$1
  shift
  run_recorded "$@" || fail "$what: rc=$?: $(tail -2 "$log")"
  grep -q "libtendril_dynamics_plugin" "$loaded" && grep -q "libtorch" "$loaded" ||
    fail "$what did not load the plugin and LibTorch"
}

# Linked: LibTorch is among the plugin's libraries, not the program's.
ldd "$tendril" | grep -q libtorch && fail "the program links LibTorch"
ldd "$plugin" | grep -q libtorch || fail "the plugin does not link LibTorch"
# One of each table: the plugin defines nothing of the layers below dynamics (only inline and
# template code, weak, which the program's exported copies replace) and calls the program's
# installers.
nm -D --defined-only -C "$plugin" | awk '$2 ~ /^[TDBR]$/' | grep "tendril::" |
  grep -v "tendril::dynamics::\|tendril::apps::run_model_\|tendril::apps::continue_stopped_fit" >own.txt
[ -s own.txt ] && fail "the plugin has its own copy of lower layers: $(head -3 own.txt)"
for installer in "tendril::envs::install_dynamics_model_loader" "tendril::nn::install_feature_head_kind"; do
  nm -D --undefined-only -C "$plugin" | grep -q "$installer" || fail "the plugin does not call $installer"
  nm -D --defined-only -C "$tendril" | grep -q " T $installer" || fail "the program does not export $installer"
done

# Commands without learned models start without it, a training run and its resumption included.
cd "$source" || exit 1
without_torch "--version" "$tendril" --version
without_torch "list envs" "$tendril" list envs
without_torch "help" "$tendril" help
without_torch "train (PPO, Pendulum)" "$tendril" train configs/ppo/pendulum.yaml -o "$scratch/ppo" \
  --quiet --set n_timesteps=8192 --set checkpoint_freq=4096 --set eval.freq=0 --stop-at 4096
without_torch "resume (PPO, Pendulum)" "$tendril" resume "$scratch/ppo" --quiet
[ -s "$scratch/ppo/model.policy" ] || fail "the PPO run did not finish"

# The model commands load it. A fit stopped by SIGTERM after its first epoch continues with
# `tendril resume`.
fit=$scratch/fit
LD_DEBUG=files LD_DEBUG_OUTPUT=$scratch/fit_ld "$tendril" model fit \
  configs/dynamics/sma_stiff_seq2seq.yaml -o "$fit" --quiet --set training.epochs=3 \
  --set training.windows_per_epoch=512 --set evaluation.horizons_s=[2] >"$scratch/fit.log" 2>&1 &
pid=$!
for _ in $(seq 600); do
  [ "$(cat "$fit/progress.csv" 2>/dev/null | wc -l)" -ge 2 ] && break
  sleep 0.1
done
kill -TERM $pid
wait $pid
rc=$?
grep -q "libtorch" "$scratch"/fit_ld.* || fail "model fit did not load LibTorch"
[ $rc -eq 143 ] && [ -f "$fit/fit.ckpt" ] || fail "model fit stopped by SIGTERM: rc=$rc: $(tail -2 "$scratch/fit.log")"
with_torch "resume (model fit)" "$tendril" resume "$fit" --quiet
[ -s "$fit/model.tdm" ] && [ ! -e "$fit/fit.ckpt" ] && grep -q "3 epochs" "$log" ||
  fail "the fit did not continue to its end: $(tail -3 "$log")"
with_torch "model eval" "$tendril" model eval "$fit" data/sma_limb/stiff_exploration_prepared.csv \
  --horizons 2
grep -q "RMSE angle" "$log" || fail "model eval printed no errors: $(tail -2 "$log")"

# A learned-model environment and a learned-model head: the plugin's model loader and head kinds
# are the ones the program's environments and algorithms find.
policy=$scratch/policy
with_torch "train (learned model, LK encoder head)" "$tendril" train \
  configs/sma_limb/learned_reach_sac_lk_encoder.yaml -o "$policy" --quiet \
  --set env.params.model="$fit" --set algo.head.model="$fit" --set env.n_envs=2 \
  --set n_timesteps=200 --set algo.learning_starts=100 --set algo.buffer_size=1000 \
  --set eval.freq=0 --set eval.episodes=2 --set eval.n_envs=2
[ -s "$policy/model.policy" ] || fail "no policy trained on the learned model"
with_torch "run (learned model, LK encoder head)" "$tendril" run "$policy" --episodes 1
grep -q "SmaLimb/LearnedReach-v0" "$log" || fail "run: $(tail -2 "$log")"

# Without the plugin: an error naming the file looked for, and no run directory.
mkdir -p "$scratch/alone" && cp "$tendril" "$scratch/alone/tendril"
"$scratch/alone/tendril" model eval "$fit" data/sma_limb/stiff_exploration_prepared.csv >"$log" 2>&1
rc=$?
[ $rc -eq 1 ] && grep -q "$scratch/alone/libtendril_dynamics_plugin.so: not found" "$log" ||
  fail "model eval without the plugin: rc=$rc: $(tail -2 "$log")"
"$scratch/alone/tendril" train configs/sma_limb/learned_reach_sac_lk_encoder.yaml \
  -o "$scratch/alone/run" --set env.params.model="$fit" --set algo.head.model="$fit" >"$log" 2>&1
rc=$?
[ $rc -eq 1 ] && grep -q "$scratch/alone/libtendril_dynamics_plugin.so: not found" "$log" ||
  fail "train on a learned model without the plugin: rc=$rc: $(tail -2 "$log")"
[ -e "$scratch/alone/run" ] && fail "a run directory was made although the plugin is missing"
TENDRIL_DYNAMICS_PLUGIN=$scratch/elsewhere.so "$tendril" run "$policy" >"$log" 2>&1
grep -q "$scratch/elsewhere.so: not found" "$log" || fail "TENDRIL_DYNAMICS_PLUGIN: $(tail -2 "$log")"
"$scratch/alone/tendril" list envs >/dev/null || fail "list envs needs the plugin"

[ $failures -eq 0 ] && echo "ok: LibTorch is loaded by the commands that need it, and only by them"
exit $failures
