#!/usr/bin/env bash
# The safety margin as an input of both agents (observe_margin: the observation's sixth entry is
# d, the distance to the disc and the walls) under the Table 6.1 co-training of the speed-controlled
# Dubins car, beside the same co-training without it, seeds 0–4 at 60k steps each
# (docs/results/safety_filter.md). Trains what is missing (one run at a time, nice), then
# evaluates every run on the same 100 episodes (reset seeds 0–99) at ε₂ = 0 and at Algorithm 3's
# ε₂, and maps its learned V on the slice heading 0, t = 0 (41 × 41 points over ±2.5 m), counting
# the points with V > 0 in the safe ring (outside the disc, inside the walls), inside the disc
# (r < 0.9 m) and outside the walls (max(|x|, |y|) > 2.1 m).
#   bash docs/results/safety_filter/margin_feature.sh    # writes safety_filter/margin_feature.csv
set -euo pipefail
cd "$(dirname "$0")/../../.."
T=${TENDRIL:-build/apps/tendril}
R=${RUNS:-runs/safety_margin_feature}
OUT=docs/results/safety_filter/margin_feature.csv
train() {  # train <run> [overrides]
  local run=$1; shift
  [ -f "$run/model.policy" ] && return 0
  rm -rf "$run"; mkdir -p "$(dirname "$run")"
  nice -n 5 "$T" train configs/safety/dubins_sac.yaml "$@" -o "$run" --quiet > "$run.log" 2>&1
}
for s in 0 1 2 3 4; do
  train "$R/margin/seed_$s" --set seed=$s --set env.params.observe_margin=true
  train "$R/plain/seed_$s" --set seed=$s
done
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
echo "variant,seed,epsilon,task_return,task_safety_rate,filtered_return_eps0,filtered_safety_rate_eps0,interventions_eps0,filtered_return,filtered_safety_rate,interventions,v_positive_ring,v_positive_disc,v_positive_outside,v_max_ring" > "$OUT"
for variant in plain margin; do
  for s in 0 1 2 3 4; do
    run="$R/$variant/seed_$s"
    nice -n 5 "$T" safety search "$run" --seed "$s" > "$tmp/search.txt"
    epsilon=$(sed -n 's/^epsilon_2 = \([-0-9.e+]*\) .*/\1/p' "$tmp/search.txt")
    # eval.csv: epsilon, unfiltered return, std, safety rate, filtered return, std, safety rate,
    # interventions; one row per ε₂.
    nice -n 5 "$T" safety eval "$run" --seed 0 --epsilon "0,$epsilon" --episodes 100 \
      --csv "$tmp/eval.csv" > /dev/null
    at0=$(sed -n 2p "$tmp/eval.csv" | awk -F, '{print $2","$4","$5","$7","$8}')
    at_search=$(sed -n 3p "$tmp/eval.csv" | awk -F, '{print $5","$7","$8}')
    nice -n 5 "$T" safety map "$run" -o "$tmp/map.csv" --resolution 41 --axes 0,1 --fixed 0,0,0 \
      > /dev/null
    map=$(awk -F, 'NR > 1 {
        x = $1; y = $2; v = $3; r = sqrt(x * x + y * y); m = (x < 0 ? -x : x); if ((y < 0 ? -y : y) > m) m = (y < 0 ? -y : y)
        if (r > 1 && m < 2) { ring++; if (v > 0) pr++; if (nr == 0 || v > top) top = v; nr = 1 }
        if (r < 0.9) { disc++; if (v > 0) pd++ }
        if (m > 2.1) { out++; if (v > 0) po++ }
      } END { printf "%.2f,%.2f,%.2f,%.0f", pr / ring, pd / disc, po / out, top }' "$tmp/map.csv")
    echo "$variant,$s,$epsilon,$at0,$at_search,$map" >> "$OUT"
  done
done
cat "$OUT"
