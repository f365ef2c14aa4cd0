#!/usr/bin/env bash
# The fixed-speed Dubins car (speed_control false: v = 1.2 m/s, the thesis' vehicle and the
# environment's default) under the Table 6.1 co-training, with more seeds, a 5× budget and starts
# over the whole safe set, beside unconstrained SAC (docs/results/safety_filter.md). Trains what
# is missing (one run at a time, nice), then evaluates every run on the same 100 episodes (reset
# seeds 0–99, ε₂ = 0) and maps its learned V on the slice heading 0, t = 0 (41 × 41 over the box).
#   bash docs/results/safety_filter/fixed_speed.sh    # writes safety_filter/fixed_speed.csv
set -euo pipefail
cd "$(dirname "$0")/../../.."
T=${TENDRIL:-build/apps/tendril}
R=${RUNS:-runs/safety_fixed_speed}
OUT=docs/results/safety_filter/fixed_speed.csv
fixed=(--set env.params.speed_control=false)
train() {  # train <run> <config> [overrides]
  local run=$1 config=$2; shift 2
  [ -f "$run/model.policy" ] && return 0
  rm -rf "$run"; mkdir -p "$(dirname "$run")"
  nice -n 5 "$T" train "configs/safety/$config.yaml" "${fixed[@]}" "$@" -o "$run" --quiet > "$run.log" 2>&1
}
for s in 0 1 2 3 4; do train "$R/dubins_sac/seed_$s" dubins_sac --set seed=$s; done
train "$R/dubins_sac_300k/seed_0" dubins_sac --set seed=0 --set n_timesteps=300000
for s in 0 1; do train "$R/dubins_sac_anywhere/seed_$s" dubins_sac_anywhere --set seed=$s; done
train "$R/dubins_unconstrained/seed_0" dubins_unconstrained --set seed=0
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
echo "variant,seed,steps,task_return,task_safety_rate,filtered_return,filtered_safety_rate,intervention_rate,v_min,v_max,v_positive_share" > "$OUT"
for run in "$R"/dubins_sac/seed_{0,1,2,3,4} "$R"/dubins_sac_300k/seed_0 "$R"/dubins_sac_anywhere/seed_{0,1} "$R"/dubins_unconstrained/seed_0; do
  variant=$(basename "$(dirname "$run")"); seed=${run##*_}
  steps=$(sed -n 's/^n_timesteps: //p' "$run/config.yaml")
  nice -n 5 "$T" safety eval "$run" --seed 0 --epsilon 0 --episodes 100 --csv "$tmp/eval.csv" > /dev/null
  # eval.csv: epsilon, unfiltered return, std, safety rate, filtered return, std, safety rate, interventions
  row=$(tail -n 1 "$tmp/eval.csv" | awk -F, '{print $2","$4","$5","$7","$8}')
  if [ -f "$run/safety.critic" ]; then
    nice -n 5 "$T" safety map "$run" -o "$tmp/map.csv" --resolution 41 --axes 0,1 --fixed 0,0,0 > /dev/null
    map=$(awk -F, 'NR > 1 {v = $3; if (n == 0 || v < lo) lo = v; if (n == 0 || v > hi) hi = v; n++; if (v > 0) p++}
                   END {printf "%.1f,%.1f,%.3f", lo, hi, p / n}' "$tmp/map.csv")
  else
    map=",,"
  fi
  echo "$variant,$seed,$steps,$row,$map" >> "$OUT"
done
cat "$OUT"
