#!/bin/sh
# Checks that two run folders of one scenario and seed hold the same bytes in each FILE given
# (virtual mode's promise, issue 16: in both directions, whatever the machine's load); prints the
# first lines that differ.
# Usage: same_bytes_check.sh RUN_A RUN_B FILE...   (busybox sh; exits 1 when a file differs)
a=${1:?usage: same_bytes_check.sh RUN_A RUN_B FILE...}
b=${2:?usage: same_bytes_check.sh RUN_A RUN_B FILE...}
shift 2
[ $# -gt 0 ] || { echo "same_bytes_check: no file named"; exit 1; }
status=0
for f in "$@"; do
  if [ ! -s "$a/$f" ] || [ ! -s "$b/$f" ]; then
    echo "same_bytes_check: FAIL: $f missing or empty"; status=1
  elif cmp -s "$a/$f" "$b/$f"; then
    echo "same_bytes_check: $f: the same $(wc -l < "$a/$f") lines"
  else
    echo "same_bytes_check: FAIL: $f differs:"; diff "$a/$f" "$b/$f" | head -n 8; status=1
  fi
done
exit $status
