#!/usr/bin/env bash
# Fault injection against the tendril program: kill -9 at random moments, SIGINT/SIGTERM,
# corrupted and truncated checkpoints and models, a full disk, two writers on one run
# directory, an interrupted sweep, hostile inputs. Each scenario checks that the run ends
# byte-identical to an uninterrupted one (model.policy, eval.csv, the steps of progress.csv)
# or fails with a clear error and exit status 1, never a crash.
#
# usage: chaos.sh <tendril> <configs-dir> <scenario> [trials]
# Exit status 77 marks a scenario skipped for a stated reason (ctest SKIP_RETURN_CODE).
set -uo pipefail
T=$1
CONFIGS=$2
SCENARIO=$3
TRIALS=${4:-8}
WORK=$(mktemp -d "${TMPDIR:-/tmp}/tendril_chaos_${SCENARIO}_XXXXXX")
trap 'rm -rf "$WORK"' EXIT
cd "$WORK" || exit 1
RANDOM=$((${CHAOS_SEED:-12345} + ${#SCENARIO}))

PPO="$CONFIGS/ppo/pendulum.yaml"
# ~5 s of training, a checkpoint every 8192 steps, evaluations every 20000.
SET=(--set n_timesteps=300000 --set algo.n_steps=256 --set checkpoint_freq=8192
     --set eval.freq=20000 --set eval.episodes=2 --set eval.save_best=true)

failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
# progress.csv's step column (its first column whose header is time/total_timesteps).
steps_of() { awk -F, 'NR==1{for(i=1;i<=NF;i++) if($i=="time/total_timesteps") c=i; next} {print $c}' "$1/progress.csv"; }
same_run() {  # <run> <reference>
  cmp -s "$1/model.policy" "$2/model.policy" || fail "$1: model.policy differs from $2"
  cmp -s "$1/eval.csv" "$2/eval.csv" || fail "$1: eval.csv differs from $2"
  if [ -f "$2/best_model.policy" ]; then
    cmp -s "$1/best_model.policy" "$2/best_model.policy" || fail "$1: best_model.policy differs"
  fi
  [ "$(steps_of "$1")" == "$(steps_of "$2")" ] || fail "$1: progress.csv steps differ from $2"
  local left
  left=$(find "$1" -name '*.tmp.*' | head -1)
  [ -z "$left" ] || fail "$1: temporary file left: $left"
}
# Waits up to 20 s for a file matching a glob to appear.
wait_for() { for _ in $(seq 200); do compgen -G "$1" >/dev/null && return 0; sleep 0.1; done; return 1; }
# Resumes until the run finishes; every resume must exit 0 or report no checkpoint yet.
finish() {  # <run> [config args for a restart]
  local run=$1
  shift
  for _ in 1 2 3; do
    [ -f "$run/model.policy" ] && return 0
    if compgen -G "$run/checkpoints/step_*.ckpt" >/dev/null; then
      "$T" resume "$run" --quiet >"$run.log" 2>&1 || { fail "$run: resume rc=$?: $(tail -2 "$run.log")"; return 1; }
    else
      rm -rf "$run"  # killed before its first checkpoint: nothing to resume
      "$T" train "$PPO" "${SET[@]}" -o "$run" --quiet >"$run.log" 2>&1 || { fail "$run: restart failed"; return 1; }
    fi
  done
}
reference() {  # <dir> [extra args]
  local dir=$1
  shift
  "$T" train "$PPO" "${SET[@]}" "$@" -o "$dir" --quiet >/dev/null 2>&1 || { echo "reference run failed"; exit 1; }
}

if [ "$SCENARIO" == kill9_sac ]; then
  # Off-policy with its replay buffer beside each checkpoint (~2 s of training).
  PPO="$CONFIGS/sac/pendulum.yaml"
  SET=(--set n_timesteps=6000 --set checkpoint_freq=250 --set eval.freq=1000 --set eval.episodes=2
       --set eval.save_best=true --set save_replay_buffer=true --set "algo.net_arch=[64,64]"
       --set algo.batch_size=64 --set algo.buffer_size=5000 --set algo.log_interval=250)
fi

case "$SCENARIO" in
kill9 | kill9_sac)
  reference ref
  stale=0
  for trial in $(seq "$TRIALS"); do
    run=k$trial
    "$T" train "$PPO" "${SET[@]}" -o "$run" --quiet >/dev/null 2>&1 &
    pid=$!
    sleep "$(printf '0.%03d' $((RANDOM % 1000)))"
    [ $((RANDOM % 3)) -eq 0 ] && sleep 2
    kill -9 "$pid" 2>/dev/null
    wait "$pid" 2>/dev/null
    echo "trial $trial: killed with checkpoints up to $(ls "$run/checkpoints" 2>/dev/null | sort -t_ -k2 -n | tail -1)"
    # A second kill during the resume, in half of the trials.
    if [ $((trial % 2)) -eq 0 ] && compgen -G "$run/checkpoints/step_*.ckpt" >/dev/null; then
      "$T" resume "$run" --quiet >/dev/null 2>&1 &
      pid=$!
      sleep "$(printf '0.%03d' $((RANDOM % 1000)))"
      kill -9 "$pid" 2>/dev/null
      wait "$pid" 2>/dev/null
    fi
    finish "$run" && same_run "$run" ref
    grep -q "taking over .*$run: its lock names process" "$run.log" 2>/dev/null && stale=$((stale + 1))
  done
  echo "stale locks of killed processes reported on resume: $stale of $TRIALS runs"
  # The random kills may all land before the first checkpoint or after the end (they depend on
  # how fast this machine starts and trains); one kill just after the first checkpoint leaves a
  # stale lock for certain, and its resume must say so.
  run=k_stale
  "$T" train "$PPO" "${SET[@]}" -o "$run" --quiet >/dev/null 2>&1 &
  pid=$!
  wait_for "$run/checkpoints/step_*.ckpt" || fail "$run: no checkpoint within 20 s"
  kill -9 "$pid" 2>/dev/null
  wait "$pid" 2>/dev/null
  if [ -f "$run/model.policy" ]; then
    fail "$run: finished before the kill; no stale lock to report"
  else
    finish "$run" && same_run "$run" ref
    grep -q "taking over .*$run: its lock names process" "$run.log" ||
      fail "$run: the resume did not report the killed process's stale lock"
  fi
  ;;
killtmp)
  # kill -9 while a checkpoint or replay buffer is being written (its temporary file exists).
  PPO="$CONFIGS/sac/pendulum.yaml"
  SET=(--set n_timesteps=6000 --set checkpoint_freq=250 --set eval.freq=1000 --set eval.episodes=2
       --set save_replay_buffer=true --set "algo.net_arch=[64,64]" --set algo.batch_size=64
       --set algo.buffer_size=200000 --set algo.log_interval=250)
  reference ref
  caught=0
  for trial in $(seq "$TRIALS"); do
    run=t$trial
    "$T" train "$PPO" "${SET[@]}" -o "$run" --quiet >/dev/null 2>&1 &
    pid=$!
    skip=$((RANDOM % 6))
    while kill -0 "$pid" 2>/dev/null; do
      if compgen -G "$run/checkpoints/*.tmp.*" >/dev/null; then
        if [ "$skip" -eq 0 ]; then
          kill -9 "$pid"
          caught=$((caught + 1))
          break
        fi
        skip=$((skip - 1))
        while compgen -G "$run/checkpoints/*.tmp.*" >/dev/null; do :; done
      fi
    done
    wait "$pid" 2>/dev/null
    finish "$run" && same_run "$run" ref
  done
  echo "killed during a write in $caught of $TRIALS trials"
  [ "$caught" -gt 0 ] || fail "no kill landed during a write"
  ;;
signals)
  reference ref
  for trial in $(seq "$TRIALS"); do
    signal=$([ $((trial % 2)) -eq 0 ] && echo TERM || echo INT)
    expected=$([ "$signal" == TERM ] && echo 143 || echo 130)
    run=s$trial
    "$T" train "$PPO" "${SET[@]}" -o "$run" --quiet >"$run.out" 2>&1 &
    pid=$!
    wait_for "$run/checkpoints/step_*.ckpt"
    sleep "$(printf '0.%03d' $((RANDOM % 1000)))"
    kill -"$signal" "$pid"
    wait "$pid"
    rc=$?
    if [ -f "$run/model.policy" ]; then
      same_run "$run" ref  # the signal came after the end
      continue
    fi
    [ "$rc" -eq "$expected" ] || fail "$run: SIG$signal gave rc=$rc, not $expected"
    grep -q "continue with:  tendril resume $run" "$run.out" || fail "$run: no resume hint"
    "$T" resume "$run" --quiet >/dev/null 2>&1 || fail "$run: resume failed"
    same_run "$run" ref
  done
  ;;
corrupt)
  reference ref
  "$T" train "$PPO" "${SET[@]}" -o paused --stop-at 100000 --quiet >/dev/null 2>&1
  newest=$(ls paused/checkpoints | sort -t_ -k2 -n | tail -1)
  for trial in $(seq "$TRIALS"); do
    run=c$trial
    cp -r paused "$run"
    file="$run/checkpoints/$newest"
    size=$(stat -c %s "$file")
    case $((trial % 4)) in
      0) truncate -s $((RANDOM * size / 32768)) "$file" ;;                      # truncated
      1) printf "\\x$(printf %02x $((1 << (RANDOM % 8))))" |                     # one bit flipped
           dd of="$file" bs=1 seek=$((RANDOM * size / 32768)) conv=notrunc 2>/dev/null ;;
      2) dd if=/dev/zero of="$file" bs=4096 count=1 seek=$((RANDOM * (size / 4096) / 32768)) conv=notrunc 2>/dev/null ;;
      3) : >"$file" ;;                                                           # empty
    esac
    cmp -s "$file" "paused/checkpoints/$newest" && { echo "trial $trial: no change, skipped"; continue; }
    "$T" resume "$run" --quiet >"$run.log" 2>&1 || fail "$run: resume rc=$?: $(tail -1 "$run.log")"
    grep -q "skipped .*$newest" "$run.log" || fail "$run: the corrupt checkpoint was not named"
    [ -f "$file.corrupt" ] || fail "$run: the corrupt checkpoint was not kept aside"
    same_run "$run" ref
  done
  # A model file: one flipped bit or a truncation is refused with an error, never a crash.
  for trial in $(seq "$TRIALS"); do
    cp -r ref m$trial
    file=m$trial/model.policy
    size=$(stat -c %s "$file")
    if [ $((trial % 2)) -eq 0 ]; then
      truncate -s $((RANDOM * size / 32768)) "$file"
    else
      printf '\x01' | dd of="$file" bs=1 seek=$((RANDOM * size / 32768)) conv=notrunc 2>/dev/null
    fi
    cmp -s "$file" ref/model.policy && continue
    "$T" run m$trial --episodes 1 >m$trial.log 2>&1
    rc=$?
    [ "$rc" -eq 1 ] || fail "m$trial: eval of a corrupt model gave rc=$rc: $(tail -1 m$trial.log)"
  done
  ;;
diskfull)
  if [ "$(id -u)" -ne 0 ] || ! mkdir -p disk || ! mount -t tmpfs -o size=1m tmpfs disk 2>/dev/null; then
    echo "skipped: mounting a small tmpfs needs root and mount permission"
    exit 77
  fi
  trap 'umount "$WORK/disk"; rm -rf "$WORK"' EXIT
  reference ref
  # Full from the start: a clear error naming a file, nothing reported finished.
  head -c 2000000 /dev/zero >disk/filler 2>/dev/null
  "$T" train "$PPO" "${SET[@]}" -o disk/run --quiet >full.log 2>&1
  rc=$?
  [ "$rc" -eq 1 ] || fail "full disk at start: rc=$rc"
  grep -q "No space left on device\|no space left" full.log || fail "full disk at start: $(cat full.log)"
  rm -f disk/filler
  rm -rf disk/run
  # Full in the middle (the checkpoints fill 1 MiB): the error names the file; once space is
  # back, the run resumes to the uninterrupted result.
  "$T" train "$PPO" "${SET[@]}" -o disk/run --quiet >mid.log 2>&1
  rc=$?
  [ "$rc" -eq 1 ] || fail "full disk mid-run: rc=$rc"
  grep -q "disk/run/.*No space left on device" mid.log || fail "full disk mid-run: $(cat mid.log)"
  [ -f disk/run/model.policy ] && fail "full disk mid-run: a model was written"
  mount -o remount,size=64m disk
  "$T" resume disk/run --quiet >resume.log 2>&1 || fail "resume after the disk filled: $(tail -2 resume.log)"
  same_run disk/run ref
  # A config.yaml was never left empty.
  [ -s disk/run/config.yaml ] || fail "empty config.yaml"
  ;;
concurrent)
  SET=(--set n_timesteps=100000 --set algo.n_steps=256 --set checkpoint_freq=8192
       --set eval.freq=20000 --set eval.episodes=2 --set eval.save_best=true)
  reference ref0 --set seed=0
  reference ref5 --set seed=5
  for trial in $(seq "$TRIALS"); do
    # Two resumes of one paused run.
    run=r$trial
    "$T" train "$PPO" "${SET[@]}" -o "$run" --stop-at 40000 --quiet >/dev/null 2>&1
    "$T" resume "$run" --quiet >"$run.a" 2>&1 & a=$!
    "$T" resume "$run" --quiet >"$run.b" 2>&1 & b=$!
    wait $a; rca=$?; wait $b; rcb=$?
    [ $((rca + rcb)) -eq 1 ] || fail "$run: two resumes gave rc $rca and $rcb"
    grep -q "in use by process [0-9]\|has finished" "$run.a" "$run.b" || fail "$run: no clear refusal"
    same_run "$run" ref0
    # Two new runs, seeds 0 and 5, into one directory.
    run=n$trial
    "$T" train "$PPO" "${SET[@]}" --set seed=0 -o "$run" --quiet >"$run.a" 2>&1 & a=$!
    "$T" train "$PPO" "${SET[@]}" --set seed=5 -o "$run" --quiet >"$run.b" 2>&1 & b=$!
    wait $a; rca=$?; wait $b; rcb=$?
    [ $((rca + rcb)) -eq 1 ] || fail "$run: two new runs gave rc $rca and $rcb"
    winner=$([ $rca -eq 0 ] && echo 0 || echo 5)
    grep -q "^seed: $winner$" "$run/config.yaml" || fail "$run: config.yaml is not seed $winner's"
    same_run "$run" ref$winner
  done
  ;;
sweep)
  cat >sweep.yaml <<YAML
experiment: $PPO
output: $WORK/sw
grid:
  - {key: n_timesteps, values: [60000]}
  - {key: algo.n_steps, values: [256]}
  - {key: checkpoint_freq, values: [16384]}
  - {key: eval.episodes, values: [2]}
  - {key: seed, values: [0, 1]}
YAML
  restarted=0
  for trial in $(seq "$TRIALS"); do
    rm -rf sw
    "$T" sweep run sweep.yaml --quiet >/dev/null 2>&1 &
    pid=$!
    wait_for "sw/*/config.yaml"
    [ $((trial % 2)) -eq 0 ] && sleep "$(printf '0.%03d' $((RANDOM % 1000)))"
    if [ $((trial % 3)) -eq 0 ]; then
      # Ctrl-C: the sweep stops after a checkpoint of the current run, with status 130.
      kill -INT "$pid" 2>/dev/null
      wait "$pid" 2>/dev/null
      rc=$?
      [ "$rc" -eq 130 ] || [ "$(ls sw/*/model.policy 2>/dev/null | wc -l)" -eq 2 ] ||
        fail "sweep trial $trial: SIGINT gave rc=$rc"
    else
      kill -9 "$pid" 2>/dev/null
      wait "$pid" 2>/dev/null
    fi
    "$T" sweep run sweep.yaml --quiet >sweep.log 2>&1 || fail "sweep trial $trial: rerun rc=$?: $(tail -2 sweep.log)"
    [ "$(ls sw/*/model.policy 2>/dev/null | wc -l)" -eq 2 ] || fail "sweep trial $trial: runs missing"
    grep -q "restarting" sweep.log && restarted=$((restarted + 1))
  done
  echo "runs restarted after an interruption before their first checkpoint: $restarted of $TRIALS sweeps"
  [ "$restarted" -gt 0 ] || fail "no sweep was interrupted before a first checkpoint"
  ;;
inputs)
  expect_error() {  # <pattern> <command...>: exit status 1 and the pattern in the message
    local pattern=$1
    shift
    timeout 20 "$@" >err.log 2>&1
    local rc=$?
    [ "$rc" -eq 1 ] && grep -q -- "$pattern" err.log || fail "'$*' gave rc=$rc: $(head -c 300 err.log)"
  }
  expect_usage_error() {  # <pattern> <command...>: a usage error (status 2) naming the problem
    local pattern=$1
    shift
    timeout 20 "$@" >err.log 2>&1
    local rc=$?
    [ "$rc" -eq 2 ] && grep -q -- "$pattern" err.log || fail "'$*' gave rc=$rc: $(head -c 300 err.log)"
  }
  mkdir adir
  expect_error "not a regular file" "$T" train /dev/zero -o o1
  expect_error "is a directory" "$T" train adir -o o2
  head -c 3000000 /dev/zero | tr '\0' '#' >big.yaml
  expect_error "larger than 1 MiB" "$T" train big.yaml -o o3
  expect_usage_error "at most 65536" "$T" train "$PPO" --set "seed=$(head -c 100000 /dev/zero | tr '\0' 1)" -o o4
  expect_error "algo.buffer_size" "$T" train "$CONFIGS/sac/pendulum.yaml" --set algo.buffer_size=1000000000000 -o o5
  expect_error "65536 units" "$T" train "$CONFIGS/sac/pendulum.yaml" --set "algo.net_arch=[100000,100000]" -o o6
  expect_error "learner_threads" "$T" train "$CONFIGS/sac/pendulum.yaml" --set algo.learner_threads=1000 -o o7
  expect_usage_error "needs a value" "$T" train "$PPO" -o ""
  expect_usage_error "--stop-at expects" "$T" train "$PPO" --stop-at -5 -o o8
  expect_usage_error "--stop-at expects" "$T" train "$PPO" --stop-at 12x -o o9
  reference ref --set n_timesteps=8192
  expect_usage_error "--episodes expects" "$T" run ref --episodes 3x
  expect_usage_error "--seed expects" "$T" run ref --seed -1
  expect_usage_error "--seed expects" "$T" run ref --seed 1.5
  expect_error "has finished" "$T" resume ref
  # An allocation that fails names the sizes that decide it.
  expect_error "out of memory.*algo.buffer_size = 100000000" bash -c \
    "ulimit -v 2000000; exec '$T' train '$CONFIGS/sac/pendulum.yaml' --set algo.buffer_size=100000000 -o o10"
  # eval.csv that cannot be written (here a directory in its place): an error, not lost rows.
  "$T" train "$PPO" "${SET[@]}" -o unwritable --stop-at 40000 --quiet >/dev/null 2>&1
  rm unwritable/eval.csv && mkdir unwritable/eval.csv
  expect_error "eval.csv" "$T" resume unwritable --quiet
  [ -e o1 ] || [ -e o2 ] || [ -e o3 ] && fail "a refused run left a directory"
  ;;
*)
  echo "unknown scenario $SCENARIO"
  exit 2
  ;;
esac

if [ "$failures" -gt 0 ]; then
  echo "$SCENARIO: $failures failure(s)"
  exit 1
fi
echo "$SCENARIO: all checks passed"
