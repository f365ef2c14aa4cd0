#!/usr/bin/env bash
# Learn the SMA limb's dynamics from the committed exploration data, train a reaching policy on
# the learned model, and run the policy on it — the thesis' pipeline (seed 001 ch. 4–5) in three
# commands:
#   bash examples/fit_then_train.sh [EPOCHS [STEPS]]
# Defaults: 20 epochs (about 5 min on 2 cores) and 100,000 steps (about 4 min).
set -euo pipefail
tendril=${TENDRIL:-build/apps/tendril}
epochs=${1:-20}
steps=${2:-100000}
model=runs/example_limb_model
policy=runs/example_limb_policy

# 1. The model: a Seq2Seq network predicting the next bend angles and rates from 100 readings
#    of angles and coil throttles (Table 4.1's stiff limb). model.tdm, progress.csv and the
#    test split's errors land in the run.
"$tendril" model fit configs/dynamics/sma_stiff_seq2seq.yaml -o "$model" \
  --set training.epochs="$epochs" ${EXAMPLE_FIT_SETTINGS:-}

# 2. The policy: SAC whose actor reads the model's encoder (the LK Encoder head of Table 5.1),
#    trained on the learned limb only.
"$tendril" train configs/sma_limb/learned_reach_sac_lk_encoder.yaml -o "$policy" --quiet \
  --set env.params.model="$model" --set algo.head.model="$model" \
  --set n_timesteps="$steps" ${EXAMPLE_TRAIN_SETTINGS:-}

# 3. Three episodes of the trained policy on the learned limb, with their returns.
"$tendril" run "$policy" --episodes 3
echo "trained on the learned model: $policy/model.policy"
