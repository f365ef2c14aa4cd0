#!/usr/bin/env bash
# Every file of examples/, run as its README says, with short budgets, from a scratch directory
# that sees the repository's configs/, examples/ and data/: each must finish and write what it promises.
#   run_examples.sh <source dir> <tendril program> <python package dir> <vendor dir> <scratch>
set -u
source=$1 tendril=$2 package=$3 vendor=$4 scratch=$5
rm -rf "$scratch" && mkdir -p "$scratch" && cd "$scratch" || exit 1
ln -s "$source/configs" configs
ln -s "$source/examples" examples
ln -s "$source/data" data
mkdir -p build/apps && ln -s "$tendril" build/apps/tendril
export PYTHONPATH=$package${vendor:+:$vendor/gymnasium-0.29.1:$vendor/stable-baselines3-2.3.2}
export MPLBACKEND=Agg
failures=0
step() {  # step <name> <expected output pattern> <command...>
  local name=$1 pattern=$2
  shift 2
  echo "== $name"
  if "$@" >"$name.log" 2>&1 && grep -q -- "$pattern" "$name.log"; then
    grep -- "$pattern" "$name.log" | tail -2
  else
    echo "FAIL: $name: $(tail -5 "$name.log")"
    failures=$((failures + 1))
  fi
}
# Stable-Baselines3 is not a Debian package: it comes from the vendored sources beside the
# checkout (as for tests/python) or from the interpreter; a machine with neither cannot run it.
if [ -n "$vendor" ] || /usr/bin/python3 -c "import stable_baselines3" 2>/dev/null; then
  step sb3_soft_arm "wrote sb3_arm.png" /usr/bin/python3 examples/sb3_soft_arm.py 4096
  expected_sb3=sb3_arm.png
else
  echo "sb3_soft_arm: not run, Stable-Baselines3 is neither installed nor vendored"
  expected_sb3=""
fi
step train_then_python "wrote example_arm.mp4" /usr/bin/python3 examples/train_then_python.py 100000
step seeds_sweep "seed" build/apps/tendril sweep run examples/seeds_sweep.yaml --no-figures --quiet
step seeds_report "3 runs\|± " build/apps/tendril report runs/sweeps/example_seeds
step filtered_deployment "through the safety filter at" bash examples/filtered_deployment.sh 3000
# One epoch of 512 windows, a 2 s rollout horizon, 2,000 steps of SAC learning from step 500.
export EXAMPLE_FIT_SETTINGS="--set training.windows_per_epoch=512 --set evaluation.horizons_s=[2]"
export EXAMPLE_TRAIN_SETTINGS="--set algo.learning_starts=500 --set algo.buffer_size=10000 \
--set eval.freq=0 --set eval.episodes=5"
step fit_then_train "trained on the learned model" bash examples/fit_then_train.sh 1 2000
for made in $expected_sb3 example_arm.mp4 runs/example_arm/model.policy runs/example_dubins/safety.critic \
  runs/example_limb_model/model.tdm runs/example_limb_policy/model.policy; do
  [ -s "$made" ] || { echo "FAIL: $made was not written"; failures=$((failures + 1)); }
done
[ $failures -eq 0 ] && echo "ok: every example"
exit $failures
