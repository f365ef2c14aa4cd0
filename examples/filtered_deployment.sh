#!/usr/bin/env bash
# A task policy and a safety critic co-trained on the Dubins car (seed 001 §6.4.1), its filter's
# threshold searched (Algorithm 3), then the policy run alone and through the learned safety
# filter, as it would be deployed on a robot (`tendril run --filter`).
#   bash examples/filtered_deployment.sh [STEPS]     # default 60000, a few minutes
set -euo pipefail
tendril=${TENDRIL:-build/apps/tendril}
steps=${1:-60000}
run=runs/example_dubins
"$tendril" train configs/safety/dubins_sac.yaml -o "$run" --set n_timesteps="$steps" --quiet
epsilon=$("$tendril" safety search "$run" | sed -n 's/.*epsilon_2 = \([-0-9.e+]*\).*/\1/p' | tail -1)
echo "threshold epsilon_2 = $epsilon"
echo "== the task policy alone"
"$tendril" run "$run" --episodes 20
echo "== through the safety filter"
"$tendril" run "$run" --episodes 20 --filter "$run" --epsilon "$epsilon"
