#!/bin/sh
# Checks a run of vectors/scenarios/closed_loop/tractor_autosteer_KIND_socketcan.yaml on vcan0
# (ISOBUS closed loop with a fault) from report.json and the bus capture captures/vcan0.candump:
#  controller_stop: the report passed, the ECU's watchdog tripped once and it ended disengaged with
#    exit reason 5; on the bus, guidanced's Guidance System Command (0CAD1C80) stops at ~15 s while
#    the ECU's Machine Info (0CACFF1C) goes on to the end, carrying exit reason 5 from the trip on.
#  command_loss: the report passed, >= 9 commands lost at the ECU, two engagements, engaged at the
#    end; on the bus, guidanced's commands go on through 15-16 s (the cut is at the ECU's receive
#    side), and the ECU's Machine Info says exit reason 5 after the trip, all clear at the end.
# Bus time: a candump stamp minus the run's start_unix_ns (captures/vcan0.cap). In virtual mode a
# frame from guidanced is stamped with the time the ECU takes it at: the arrival time of the host
# turn that reads it off the bus (once the bytes it may answer have left their UARTs), which
# report.json's last_command_s and the command_link_loss window use too. So guidanced's last frame
# on the bus is at last_command_s, and the frames in [15, 16) are exactly those the cut lost.
# Usage: closed_loop_isobus_fault_check.sh controller_stop|command_loss RUN_DIR   (busybox sh/awk)
kind=${1:?usage: closed_loop_isobus_fault_check.sh controller_stop|command_loss RUN_DIR}
r=${2:?usage: closed_loop_isobus_fault_check.sh controller_stop|command_loss RUN_DIR}
fail() { echo "closed_loop_isobus_fault_check $kind: FAIL: $*"; exit 1; }
j="$r/report.json" cap="$r/captures/vcan0.candump"
[ -f "$j" ] && [ -f "$cap" ] || fail "no $j or $cap"
# a field of closed_loop (4 spaces in), or of its steering_ecu object (6 spaces in)
cl() { sed -n '/^  "closed_loop": {/,/^  },/p' "$j" | sed -n "s/^    \"$1\": *\([^,]*\),*$/\1/p" | head -n 1; }
ecu() { sed -n '/^    "steering_ecu": {/,/^    },/p' "$j" | sed -n "s/^      \"$1\": *\([^,]*\),*$/\1/p" | head -n 1; }
start=$(sed -n 's/^# start_unix_ns //p' "$r/captures/vcan0.cap")
[ -n "$start" ] || fail "no start_unix_ns in $r/captures/vcan0.cap"
# bus figures: commands (count, last time, count in [15, 16), count after 16 s); Machine Info
# (count, last time, count after 15.5 s, first and last time with exit reason 5, last exit reason)
bus=$(awk -v s0="${start%?????????}" -v f0="${start#"${start%?????????}"}" '
  function hex(s,   i, v) { for (i = 1; i <= length(s); i++) v = v * 16 + index("0123456789ABCDEF", substr(s, i, 1)) - 1; return v }
  { split(substr($1, 2, length($1) - 2), ts, "."); t = (ts[1] - s0) + ts[2] / 1e6 - f0 / 1e9
    split($3, f, "#") }
  f[1] == "0CAD1C80" { nc++; lc = t; if (t >= 15 && t < 16) wc++; if (t >= 16) ac++ }
  f[1] == "0CACFF1C" { ni++; li = t; if (t >= 15.5) ai++; x = hex(substr(f[2], 9, 2)) % 64
                       if (x == 5) { if (!f5) f5 = t; l5 = t } }
  END { printf "%d %.6f %d %d %d %.3f %d %.3f %.3f %d\n", nc, lc, wc, ac, ni, li, ai, f5, l5, x }' "$cap")
# shellcheck disable=SC2086 # the ten figures, split into $1..$10
set -- $bus
cmds=$1 cmd_last=$2 cmds_15_16=$3 cmds_after_16=$4 infos=$5 info_last=$6 infos_after=$7 exit5_first=$8 exit5_last=$9 exit_last=${10}
trips=$(cl watchdog_trips) trip_s=$(cl watchdog_trip_s) last_s=$(cl last_command_s) lost=$(cl command_bytes_lost)
code=$(ecu exit_reason_code) engaged=$(ecu engaged) engagements=$(ecu engagements) frames_lost=$(ecu frames_lost)
echo "closed_loop_isobus_fault $kind: watchdog_trips=$trips watchdog_trip_s=$trip_s last_command_s=$last_s" \
     "exit_reason_code=$code engaged=$engaged engagements=$engagements command_bytes_lost=$lost frames_lost=$frames_lost"
echo "  bus: commands=$cmds last_command_t=$cmd_last in_15_16=$cmds_15_16 after_16=$cmds_after_16" \
     "machine_info=$infos last_t=$info_last after_15.5=$infos_after exit5_t=$exit5_first..$exit5_last last_exit=$exit_last"
grep -q '^  "pass": true' "$j" || { sed -n '/"criteria"/,/\]/p' "$j"; fail "the report did not pass"; }
grep -q '"transport": "socketcan"' "$j" || fail "not the socketcan transport"
[ "${trips:-0}" -ge 1 ] || fail "the watchdog never tripped"
# t1 < t2 (decimals; busybox sh has integers only)
lt() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a + 0 < b + 0) }'; }
lt "$info_last" 24.5 && fail "Machine Info stops at $info_last s (the run is 25 s)"
lt 0 "$exit5_first" || fail "no Machine Info with exit reason 5 on the bus"
lt "$exit5_first" "$trip_s" && fail "exit reason 5 on the bus at $exit5_first s, before the trip ($trip_s s)"
case $kind in
  controller_stop)
    [ "$code" = 5 ] && [ "$engaged" = false ] || fail "the ECU did not end disengaged with exit reason 5"
    ! lt "$cmd_last" 14.8 && lt "$cmd_last" 15.2 || fail "guidanced's last command on the bus at $cmd_last s"
    awk -v a="$last_s" -v b="$cmd_last" 'BEGIN { d = a - b; exit !(d < 1e-5 && d > -1e-5) }' ||
      fail "the ECU's last command at $last_s s, the bus's at $cmd_last s (not its arrival time)"
    [ "$infos_after" -ge 90 ] || fail "only $infos_after Machine Info frames after 15.5 s (10 Hz)"
    [ "$exit_last" = 5 ] || fail "the last Machine Info says exit reason $exit_last" ;;
  command_loss)
    [ "${lost:-0}" -ge 9 ] && [ "$lost" = "$frames_lost" ] || fail "command_bytes_lost $lost, frames_lost $frames_lost"
    [ "$engagements" = 2 ] && [ "$engaged" = true ] || fail "engagements $engagements, engaged $engaged"
    [ "$cmds_15_16" = "$lost" ] ||
      fail "$cmds_15_16 commands on the bus in 15-16 s, $lost lost (the cut is at the ECU's receive side)"
    [ "$cmds_after_16" -ge 80 ] || fail "only $cmds_after_16 commands after 16 s"
    lt "$exit5_last" 15.9 && fail "exit reason 5 ends at $exit5_last s, before the commands return"
    lt "$exit5_last" 16.5 || fail "exit reason 5 until $exit5_last s (no re-engagement)"
    [ "$exit_last" = 0 ] || fail "the last Machine Info says exit reason $exit_last" ;;
  *) fail "unknown kind (controller_stop or command_loss)" ;;
esac
echo "closed_loop_isobus_fault_check $kind: ok"
