#!/bin/sh
# Compares a capture's candump log with an independent `candump -L` of the same bus (issue 15.3):
# the same frames in the same order, and (unless ORDER_ONLY=1) every frame's time within TOL_US of
# the bus's once the two clocks' constant offset (the run's start UTC against the VM's clock) is
# taken out. Also asserts that the capture's time never goes backwards.
# Usage: [ORDER_ONLY=1] candump_match_check.sh CAPTURE.candump BUS.log [TOL_US]   (busybox sh/awk)
cap=${1:?usage: candump_match_check.sh CAPTURE BUS_LOG [TOL_US]}
bus=${2:?usage: candump_match_check.sh CAPTURE BUS_LOG [TOL_US]}
tol=${3:-1000}
fail() { echo "candump_match_check: FAIL: $*"; exit 1; }
[ -s "$cap" ] || fail "no capture $cap"
[ -s "$bus" ] || fail "no bus log $bus"
# "(secs.micros) iface frame" -> "micros_since_epoch frame" (integers exact in awk's doubles)
norm() { grep '^(' "$1" | sed 's/^(\([0-9]*\)\.\([0-9]*\)) [^ ]* \([^ ]*\).*/\1 \2 \3/'; }
norm "$cap" >cap.norm
norm "$bus" >bus.norm
nc=$(wc -l <cap.norm)
nb=$(wc -l <bus.norm)
echo "candump_match: capture $nc frames, bus $nb frames"
[ "$nc" -gt 0 ] || fail "the capture holds no frame"
[ "$nc" -eq "$nb" ] || fail "the capture holds $nc frames, the bus carried $nb"
awk -v tol="$tol" -v order_only="${ORDER_ONLY:-0}" '
  # microseconds: "1" prefixed, since busybox awk reads a leading 0 as octal
  NR == FNR { t[FNR] = $1 * 1000000 + ("1" $2) - 1000000; f[FNR] = $3; next }
  {
    tb = $1 * 1000000 + ("1" $2) - 1000000
    if ($3 != f[FNR]) { printf "frame %d: capture %s, bus %s\n", FNR, f[FNR], $3; bad = 1; exit }
    if (FNR > 1 && t[FNR] < t[FNR - 1]) { printf "capture time went back at frame %d\n", FNR; bad = 1; exit }
    d = t[FNR] - tb
    if (FNR == 1) { d0 = d; lo = 0; hi = 0 }
    e = d - d0
    if (e < lo) lo = e
    if (e > hi) hi = e
    if (e < 0) e = -e
    if (e > worst) { worst = e; at = FNR }
  }
  END {
    if (bad) exit 1
    printf "candump_match: order identical; capture - bus time spread %d..%d us (worst %d us at frame %d)\n", lo, hi, worst, at
    if (!order_only && hi - lo > tol) { printf "time spread over %d us\n", tol; exit 1 }
  }' cap.norm bus.norm || fail "the capture does not match the bus"
echo "candump_match_check: ok"
