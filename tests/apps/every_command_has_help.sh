#!/usr/bin/env bash
# Every command `tendril help` lists answers --help and -h with its usage (status 0), and names
# its options; a misspelt option is a usage error (status 2) that names it.
set -u
tendril=$1
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
commands=$("$tendril" help | sed -n '/^commands:/,/^$/p' | sed -n 's/^  \([a-z][a-z -]*[a-z]\)  .*/\1/p')
[ "$(echo "$commands" | wc -l)" -ge 20 ] || fail "tendril help lists too few commands: $commands"
while read -r command; do
  [ -n "$command" ] || continue
  [ "$command" = plot ] && continue  # its options are the plotting package's (its own --help)
  for flag in --help -h; do
    out=$("$tendril" $command $flag 2>&1) || fail "'$command $flag' exited $?"
    echo "$out" | grep -q "^usage: tendril $command" || fail "'$command $flag': no usage line"
  done
  out=$("$tendril" $command --no-such-option 2>&1)
  rc=$?
  [ $rc -eq 2 ] || fail "'$command --no-such-option' exited $rc"
  echo "$out" | grep -q -- "--no-such-option" || fail "'$command --no-such-option': $out"
done <<<"$commands"
# A group word with --help or -h lists its commands, as `tendril help GROUP` does.
groups=$(echo "$commands" | awk 'NF > 1 {print $1}' | sort -u)
[ -n "$groups" ] || fail "no command groups found"
for group in $groups; do
  expected=$("$tendril" help "$group")
  for flag in --help -h; do
    out=$("$tendril" "$group" $flag 2>&1) || fail "'$group $flag' exited $?"
    [ "$out" = "$expected" ] || fail "'$group $flag' differs from 'tendril help $group': $out"
  done
done
"$tendril" --version | grep -q '^tendril [0-9]' || fail "--version"
[ $failures -eq 0 ] && echo "ok: $(echo "$commands" | wc -l) commands"
exit $failures
