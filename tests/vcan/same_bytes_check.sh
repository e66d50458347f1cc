#!/bin/sh
# Checks that two run folders of one scenario and seed hold the same bytes in each FILE given
# (virtual mode's promise, issue 16: in both directions, whatever the machine's load); prints the
# first lines that differ.
# Usage: same_bytes_check.sh RUN_A RUN_B FILE...   (busybox sh; exits 1 when a file differs)
a=${1:?usage: same_bytes_check.sh RUN_A RUN_B FILE...}
b=${2:?usage: same_bytes_check.sh RUN_A RUN_B FILE...}
shift 2
[ $# -gt 0 ] || { echo "same_bytes_check: no file named"; exit 1; }
# A .cap file's wall-clock column (t_wall_ns, the 4th of each record) is left out: 0 in virtual
# mode, the write's time in a lockstep run (real time or scaled), the bytes otherwise the same.
status=0
nowall() { awk '/^#/ {print; next} {$4 = "0"; print}' "$1"; }
for f in "$@"; do
  if [ ! -s "$a/$f" ] || [ ! -s "$b/$f" ]; then
    echo "same_bytes_check: FAIL: $f missing or empty"; status=1
  elif case $f in *.cap) nowall "$a/$f" >"$a/$f.nowall" && nowall "$b/$f" >"$b/$f.nowall" &&
       cmp -s "$a/$f.nowall" "$b/$f.nowall" ;; *) false ;; esac; then
    echo "same_bytes_check: $f: the same $(wc -l < "$a/$f") lines (wall-clock column aside)"
  elif cmp -s "$a/$f" "$b/$f"; then
    echo "same_bytes_check: $f: the same $(wc -l < "$a/$f") lines"
  else
    echo "same_bytes_check: FAIL: $f differs:"; diff "$a/$f" "$b/$f" | head -n 8; status=1
  fi
done
exit $status
