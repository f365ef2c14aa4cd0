#!/usr/bin/env bash
# Case 3's φ = 10 arm (Naughton et al. 2021, Fig. 8): does it stop short of the target for want of
# exploration? Trains (what is missing, one run at a time) the contact arm of seeds 0-2, then the
# penalty arm warm-started from each seed's contact policy (2M steps) and one penalty arm from
# scratch at 10M steps, and evaluates each policy for one deterministic episode (reset seed 0)
# in the penalty environment: its return there, and the per-step means of the tip-target distance
# and of the elements intersecting a cylinder (`contacts`); beside them each run's own last
# training return and final evaluation (for the contact arm: in the contact environment).
#   bash docs/results/elastica/penalty_phi10.sh    # writes elastica/studies/penalty_phi10.csv
set -euo pipefail
cd "$(dirname "$0")/../../.."
T=${TENDRIL:-build/apps/tendril}
E=configs/elastica/structured_obstacles_ppo_manual.yaml
P=(--set env.params.obstacle_mode=penalty --set env.params.penalty_weight=10)
OUT=docs/results/elastica/studies/penalty_phi10.csv
train() {  # train <run> [overrides]
  local run=$1; shift
  [ -f "$run/model.policy" ] && return 0
  rm -rf "$run"; mkdir -p "$(dirname "$run")"
  nice -n 5 "$T" train "$E" "$@" -o "$run" --quiet > "$run.log" 2>&1
}
"$T" sweep run configs/elastica/sweeps/structured_obstacles_ppo_manual_seeds.yaml
for s in 0 1 2; do
  train runs/elastica_phi10/from_contact/seed_$s "${P[@]}" --set seed=$s \
    --set warm_start=runs/sweeps/structured_obstacles_ppo_manual/seed_$s
done
train runs/elastica_phi10/10m/seed_0 "${P[@]}" --set seed=0 --set n_timesteps=10000000
echo "variant,seed,steps,training_return_final,eval_return_final,penalty_return,distance_m,intersecting_elements,wall_s" > "$OUT"
row() {  # row <variant> <seed> <run>: the run's policy in the penalty environment
  local run=$3
  local means; means=$("$T" run "$run" --episodes 1 "${P[@]}" |
    awk '$1 == "return" {r = $2} /per step/ {p = 1} p && $1 == "distance" {d = $2}
         p && $1 == "contacts" {c = $2} END {printf "%.0f,%s,%s", r, d, c}')
  local progress; progress=$(tail -n 1 "$run/progress.csv")
  local header; header=$(head -n 1 "$run/progress.csv")
  local train; train=$(awk -F, -v h="$header" -v r="$progress" 'BEGIN {
      n = split(h, k, ","); split(r, v, ",")
      for (i = 1; i <= n; i++) { if (k[i] == "rollout/ep_rew_mean") m = v[i]; if (k[i] == "time/total_timesteps") t = v[i]; if (k[i] == "time/time_elapsed") w = v[i] }
      printf "%d,%.0f,%.0f", t, m, w }')
  local final; final=$(tail -n 1 "$run/eval.csv" | cut -d, -f2)
  IFS=, read -r steps train_return wall <<< "$train"
  printf "%s,%s,%s,%s,%.0f,%s,%s\n" "$1" "$2" "$steps" "$train_return" "$final" "$means" "$wall" >> "$OUT"
}
for s in 0 1 2; do row contact_policy_under_penalty "$s" runs/sweeps/structured_obstacles_ppo_manual/seed_$s; done
for s in 0 1 2; do row from_contact "$s" runs/elastica_phi10/from_contact/seed_$s; done
row from_scratch_10m 0 runs/elastica_phi10/10m/seed_0
cat "$OUT"
