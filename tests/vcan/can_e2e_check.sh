#!/bin/sh
# Checks a run of vectors/scenarios/can_imu.yaml (emulator → vcan0 → navd → vcan0 → evaluation):
# the report passed, the MCU's J1939 frames went out and navd read every one of them (its socket
# dropped none), navd's NMEA 2000 frames (129029 among them) came back, and the harness lost none.
# Usage: can_e2e_check.sh RUN_DIR   (busybox sh; prints the figures, exits 1 on any failure)
r=${1:?usage: can_e2e_check.sh RUN_DIR}
fail() { echo "can_e2e_check: FAIL: $*"; exit 1; }
num() { sed -n "s/.*\"$1\": *\([0-9][0-9]*\).*/\1/p" "$r/report.json" | head -n 1; }
[ -f "$r/report.json" ] || fail "no $r/report.json"
grep -q '^  "pass": true' "$r/report.json" || { cat "$r/report.json"; fail "the report did not pass"; }
sent=$(num frames_sent); received=$(num frames_received); lost=$(num lost); pos=$(num 129029)
# the estimate's RMSE: the first horizontal_rmse_m after "metrics" (report.json, indented by 2)
rmse=$(awk '/^  "metrics"/ {m = 1} m && /"horizontal_rmse_m"/ {gsub(/[^0-9.e-]/, "", $2); print $2; exit}' "$r/report.json")
wall=$(sed -n 's/.*"wall_time_s": *\([0-9.e-]*\).*/\1/p' "$r/report.json" | head -n 1)
line=$(grep 'navd: can_imu' "$r/estimator.stderr")
navd_frames=$(echo "$line" | sed -n 's/.* frames=\([0-9]*\) .*/\1/p')
navd_drops=$(echo "$line" | sed -n 's/.* drops=\([0-9]*\) .*/\1/p')
navd_imu=$(echo "$line" | sed -n 's/.* imu=\([0-9]*\) .*/\1/p')
echo "can_e2e: harness sent=$sent received=$received lost=$lost 129029_frames=$pos;" \
     "navd read=$navd_frames drops=$navd_drops imu_samples=$navd_imu; rmse_m=$rmse wall_s=$wall"
echo "navd: $line"
[ "${sent:-0}" -gt 0 ] || fail "no frame was sent to navd"
[ "${received:-0}" -gt 0 ] || fail "no frame came back from navd"
[ "${pos:-0}" -gt 0 ] || fail "no 129029 frame came back"
[ "${lost:-1}" -eq 0 ] || fail "the harness lost $lost frame(s)"
[ -n "$line" ] || fail "navd printed no can_imu counters"
[ "${navd_drops:-1}" -eq 0 ] || fail "navd's socket dropped $navd_drops frame(s)"
[ "${navd_frames:-0}" -eq "$sent" ] || fail "navd read $navd_frames of the $sent frames sent"
[ "${navd_imu:-0}" -gt 0 ] || fail "navd made no IMU sample of the frames"
grep -c '^(' "$r/captures/vcan0.candump" >/dev/null || fail "empty candump capture"
echo "can_e2e_check: ok"
