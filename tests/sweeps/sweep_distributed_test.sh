#!/usr/bin/env bash
# A sweep trained by two MPI ranks (mpirun -n 2) and by the tasks of its Slurm job-array script
# (run one after the other with SLURM_ARRAY_TASK_ID set, as Slurm would), checked against the
# same sweep trained by one process: every run trained once, by its rank, into one tree; the
# same policies; one summary; a second launch keeps everything.
#   sweep_distributed_test.sh <tendril> <mpirun>
set -uo pipefail
T=$1
MPIRUN=$2
command -v "$MPIRUN" >/dev/null || { echo "FAIL: no $MPIRUN (scripts/setup installs openmpi-bin)"; exit 1; }
WORK=$(mktemp -d "${TMPDIR:-/tmp}/tendril_sweep_distributed_XXXXXX")
trap 'rm -rf "$WORK"' EXIT
cd "$WORK" || exit 1
# OpenMPI refuses to start as root unless told that is intended (containers, CI).
if [ "$(id -u)" -eq 0 ]; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi

failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

cat >base.yaml <<'YAML'
algorithm: ppo
env: {id: Pendulum-v1, n_envs: 2}
algo: {n_steps: 64}
n_timesteps: 2048
checkpoint_freq: 512
eval: {freq: 1024, episodes: 2}
seed: 0
YAML
for name in one mpi slurm; do
  cat >"$name.yaml" <<YAML
experiment: base.yaml
grid:
  - {key: algo.n_steps, values: [64, 128]}
  - {key: seed, values: [0, 1, 2]}
output: $name
YAML
done
runs="n_steps_64-seed_0 n_steps_64-seed_1 n_steps_64-seed_2 n_steps_128-seed_0 n_steps_128-seed_1 n_steps_128-seed_2"

"$T" sweep run one.yaml --quiet --no-figures >one.log 2>&1 || fail "one process: rc=$?: $(tail -3 one.log)"

# --- MPI: two ranks, runs 0, 2, 4 on rank 0 and 1, 3, 5 on rank 1
"$MPIRUN" -n 2 --oversubscribe --bind-to none "$T" sweep run mpi.yaml --quiet >mpi.log 2>&1 ||
  fail "mpirun -n 2: rc=$?: $(tail -5 mpi.log)"
[ "$(grep -c '^start,.*,[01],2$' mpi/sweep_log.csv)" -eq 2 ] || fail "sweep_log.csv: $(cat mpi/sweep_log.csv)"
for i in 0 1 2 3 4 5; do
  run=$(echo $runs | cut -d' ' -f$((i + 1)))
  rank=$((i % 2))
  [ "$(grep -c "\] mpi/$run: started" mpi.log)" -eq 1 ] || fail "$run was not started exactly once"
  grep -q "^\[rank $rank/2\] \[$((i + 1))/6\] mpi/$run: started" mpi.log || fail "$run not trained by rank $rank"
  cmp -s "one/$run/model.policy" "mpi/$run/model.policy" || fail "$run: model.policy differs from one process's"
  [ ! -s "mpi/$run/run.lock" ] || fail "$run: run.lock still names a process"
done
[ -f mpi/summary/summary.md ] && [ -f mpi/summary/training.png ] && [ -f mpi/summary/evaluation.png ] &&
  [ -f mpi/summary/final.png ] ||
  fail "no summary with figures: $(ls mpi/summary 2>&1)"
[ "$(grep -c '^summary: ' mpi.log)" -eq 1 ] || fail "the summary was not written exactly once"
"$T" sweep summarize one.yaml --no-figures >/dev/null || fail "aggregate-only failed"
# The same runs, the same final evaluations (columns 1-8; steps/s differ).
diff <(cut -d, -f1-8 one/summary/configurations.csv) <(cut -d, -f1-8 mpi/summary/configurations.csv) ||
  fail "configurations.csv differs between one process and two ranks"
# A second launch with another rank count keeps every run.
"$MPIRUN" -n 3 --oversubscribe --bind-to none "$T" sweep run mpi.yaml --quiet --no-figures >again.log 2>&1 ||
  fail "second mpirun: rc=$?"
[ "$(grep -c 'finished earlier, kept' again.log)" -eq 6 ] || fail "second launch: $(cat again.log)"

# --- Slurm: three array tasks, each taking two runs
"$T" sweep slurm slurm.yaml --tasks 3 --time 00:10:00 >slurm.log 2>&1 || fail "--slurm: rc=$?"
script=slurm/slurm/sweep.sbatch
grep -qx '#SBATCH --array=0-2' "$script" || fail "array range: $(grep array "$script")"
grep -qx "exec '$T' sweep run '$WORK/slurm.yaml' --rank \"\$SLURM_ARRAY_TASK_ID\" --ranks 3 --quiet" "$script" ||
  fail "task command: $(grep exec "$script")"
for task in 2 0 1; do
  (cd / && SLURM_ARRAY_TASK_ID=$task bash "$WORK/$script") >"task$task.log" 2>&1 ||
    fail "array task $task: rc=$?: $(tail -3 "task$task.log")"
done
grep -q '^summary: ' task1.log || fail "the last task did not write the summary"
grep -q '^summary: ' task2.log task0.log && fail "a task wrote the summary before every run had finished"
for run in $runs; do
  cmp -s "one/$run/model.policy" "slurm/$run/model.policy" || fail "slurm $run: model.policy differs"
done

[ "$failures" -eq 0 ] && echo "ok: one process, mpirun -n 2 and 3 Slurm array tasks trained the same sweep"
exit $((failures > 0))
