#!/usr/bin/env bash
# The README's "First steps", run as written: each command line of that block, in order, from a
# scratch directory that sees the repository's configs/ (the dashboard is checked to answer, then
# stopped). A command the README shows must work for a new user.
#   readme_first_steps.sh <source dir> <tendril program> <scratch dir>
set -u
source=$1 tendril=$2 scratch=$3
rm -rf "$scratch" && mkdir -p "$scratch" && cd "$scratch" || exit 1
ln -s "$source/configs" configs
commands=$(sed -n '/^## First steps/,/^## /p' "$source/README.md" | sed -n 's/^    build\/apps\/tendril //p' |
  sed 's/  *#.*$//')
[ "$(echo "$commands" | wc -l)" -ge 6 ] || { echo "FAIL: no First steps block in README.md"; exit 1; }
failures=0
while read -r line; do
  read -r -a words <<<"$line"
  echo "== tendril $line"
  if [ "${words[0]}" = serve ]; then
    "$tendril" "${words[@]}" --port 18050 >serve.log 2>&1 &
    pid=$!
    for _ in $(seq 50); do
      python3 -c 'import urllib.request; urllib.request.urlopen("http://127.0.0.1:18050/api/index")' \
        2>/dev/null && break
      sleep 0.2
    done
    python3 -c 'import urllib.request,sys; sys.exit(b"pendulum" not in urllib.request.urlopen("http://127.0.0.1:18050/api/index").read())' ||
      { echo "FAIL: the dashboard does not list runs/pendulum: $(cat serve.log)"; failures=$((failures + 1)); }
    kill "$pid"; wait "$pid" 2>/dev/null
    continue
  fi
  "$tendril" "${words[@]}" >out.log 2>&1 ||
    { echo "FAIL: exit $?: $(tail -5 out.log)"; failures=$((failures + 1)); }
  tail -3 out.log
done <<<"$commands"
for made in runs/pendulum/model.policy runs/arm/model.policy runs/arm/episodes/episode_0000.tep arm.mp4 \
  arm_policy.h; do
  [ -s "$made" ] || { echo "FAIL: $made was not written"; failures=$((failures + 1)); }
done
[ $failures -eq 0 ] && echo "ok: the README's first steps"
exit $failures
