#!/bin/sh
# Checks a run of vectors/scenarios/closed_loop/tractor_autosteer.yaml on vcan0 (guidanced's
# Guidance System Command → the emulated steering ECU → Machine Info / Wheel-based Speed back):
# the report passed, the transport was SocketCAN, no command was missing or refused, the ECU stayed
# engaged, and the bus capture holds both directions (0CAD1C80 from guidanced, 0CACFF1C and
# 0CFE481C from the ECU).
# Usage: closed_loop_isobus_check.sh RUN_DIR   (busybox sh; prints the figures, exits 1 on failure)
r=${1:?usage: closed_loop_isobus_check.sh RUN_DIR}
fail() { echo "closed_loop_isobus_check: FAIL: $*"; exit 1; }
num() { sed -n "s/.*\"$1\": *\([0-9][0-9.e-]*\).*/\1/p" "$r/report.json" | head -n 1; }
[ -f "$r/report.json" ] || fail "no $r/report.json"
grep -q '^  "pass": true' "$r/report.json" || { cat "$r/report.json"; fail "the report did not pass"; }
grep -q '"transport": "socketcan"' "$r/report.json" || fail "not the socketcan transport"
missing=$(num missing_commands); accepted=$(num commands_accepted); invalid=$(num invalid_lines)
xte=$(num cross_track_mean_abs_m); wall=$(num wall_time_s)
cmd=$(grep -c ' 0CAD1C80#' "$r/captures/vcan0.candump"); info=$(grep -c ' 0CACFF1C#' "$r/captures/vcan0.candump")
speed=$(grep -c ' 0CFE481C#' "$r/captures/vcan0.candump")
echo "closed_loop_isobus: commands_accepted=$accepted missing=$missing invalid=$invalid" \
     "bus: commands=$cmd machine_info=$info wheel_speed=$speed; mean_abs_xte_m=$xte wall_s=$wall"
[ "${missing:-1}" -eq 0 ] || fail "$missing command(s) missing"
[ "${invalid:-1}" -eq 0 ] || fail "$invalid command(s) refused"
[ "${accepted:-0}" -gt 300 ] || fail "only ${accepted:-0} commands accepted"
[ "${cmd:-0}" -ge "${accepted:-0}" ] || fail "the capture holds $cmd commands of $accepted accepted"
[ "${info:-0}" -gt 300 ] || fail "only ${info:-0} Machine Info frames on the bus"
[ "${speed:-0}" -gt 300 ] || fail "only ${speed:-0} Wheel-based Speed frames on the bus"
grep -q '"engaged": true' "$r/report.json" || fail "the ECU was not engaged at the end"
