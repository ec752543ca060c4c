#!/usr/bin/env bash
# Runs the command given (the adversary with a budget its meshes exceed) and passes only if it
# exits with status 1 and names a violation: a crash or a bad-input error (status 2) fails.
# usage: expect_violation.sh COMMAND [ARGUMENTS...]
output=$("$@" 2>&1)
status=$?
printf '%s\n' "$output"
if [ "$status" -ne 1 ]; then
  echo "FAIL: exit status $status, expected 1 (a violation)"
  exit 1
fi
if ! grep -q '^violation: ' <<< "$output"; then
  echo "FAIL: exit status 1 without a 'violation:' line"
  exit 1
fi
echo "OK: the violation fails the run"
