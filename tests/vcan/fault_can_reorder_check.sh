#!/bin/sh
# Checks a run of vectors/scenarios/vcan/fault_can_reorder.yaml (reordered CAN frames into navd):
# the report passed (its criteria: output rate, injections, navd's imu_can_unpaired and
# imu_link_errors flag, recovery time, RMSE), the harness swapped frames, navd's health object
# counted unpaired frames and agrees with the counters navd prints at exit, and the fault recovered.
# Usage: fault_can_reorder_check.sh RUN_DIR   (busybox sh; prints the figures, exits 1 on any failure)
r=${1:?usage: fault_can_reorder_check.sh RUN_DIR}
fail() { echo "fault_can_reorder_check: FAIL: $*"; exit 1; }
# a value of report.json's metric_table (keys are sorted: baselines and baseline_table come first)
val() { sed -n '/^  "metric_table"/,/^  }/p' "$r/report.json" | sed -n "s/.*\"$1\": *\([0-9][0-9.e+-]*\).*/\1/p" | head -n 1; }
[ -f "$r/report.json" ] || fail "no $r/report.json"
# the scenario's only fault: the first "count" of fault_injections (its keys are sorted)
swapped=$(awk '/^  "fault_injections"/ {f = 1} f && /"count"/ {gsub(/[^0-9]/, "", $2); print $2; exit}' "$r/report.json")
grep -q '"kind": "can_reorder"' "$r/report.json" || fail "no can_reorder in fault_injections"
unpaired=$(val navd.imu_can_unpaired)
flag=$(val navd.flag.imu_link_errors)
recovery=$(val fault_recovery_time_s)
rmse=$(val horizontal_rmse_m)
maxerr=$(val max_horizontal_error_m)
rate=$(val output_rate_hz)
line=$(grep 'navd: can_imu' "$r/estimator.stderr")
navd_unpaired=$(echo "$line" | sed -n 's/.* unpaired=\([0-9]*\) .*/\1/p')
echo "fault_can_reorder: pairs_swapped=$swapped navd_health_unpaired=$unpaired navd_exit_unpaired=$navd_unpaired" \
     "imu_link_errors_flag=$flag recovery_s=$recovery rmse_m=$rmse max_error_m=$maxerr output_rate_hz=$rate"
echo "navd: $line"
grep -q '^  "pass": true' "$r/report.json" || { sed -n '/"criteria"/,/\]/p' "$r/report.json"; fail "the report did not pass"; }
[ "${swapped:-0}" -gt 0 ] || fail "no CAN frame pair was swapped"
[ -n "$unpaired" ] || fail "navd's health object has no imu_can_unpaired"
[ "${unpaired%.*}" -gt 0 ] || fail "navd counted no unpaired frame"
[ -n "$navd_unpaired" ] || fail "navd printed no can_imu counters"
# the last JSON line is at most one solution period before exit: its count cannot exceed the final one
[ "${unpaired%.*}" -le "$navd_unpaired" ] || fail "health unpaired $unpaired > navd's final $navd_unpaired"
[ -n "$recovery" ] || fail "the fault never recovered"
echo "fault_can_reorder_check: ok"
