#!/usr/bin/env bash
# `tendril adapt` never overwrites: an output directory that is not an adaptation of the same
# configuration is refused, naming why, and left as it was.
#   adapt_output_test.sh <source dir> <tendril program> <scratch dir>
set -u
source=$1 tendril=$2 scratch=$3
rm -rf "$scratch" && mkdir -p "$scratch" && cd "$scratch" || exit 1
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
config=$source/configs/pneumatic_arm/adapt_gprca.yaml

mkdir other && echo "precious" >other/notes.txt
"$tendril" adapt "$config" -o other >log 2>&1
rc=$?
[ $rc -eq 1 ] && grep -q "not an adaptation output; nothing is overwritten" log ||
  fail "a foreign directory: rc=$rc: $(tail -2 log)"
[ "$(ls other)" = notes.txt ] && [ "$(cat other/notes.txt)" = precious ] || fail "other/ was changed"

mkdir earlier && printf 'method: boac\n' >earlier/config.yaml
"$tendril" adapt "$config" -o earlier >log 2>&1
rc=$?
[ $rc -eq 1 ] && grep -q "another configuration" log || fail "another configuration: rc=$rc: $(tail -2 log)"
[ "$(cat earlier/config.yaml)" = "method: boac" ] && [ "$(ls earlier)" = config.yaml ] ||
  fail "earlier/ was changed"
[ $failures -eq 0 ] && echo "ok: adapt refuses outputs it did not write for this configuration"
exit $failures
