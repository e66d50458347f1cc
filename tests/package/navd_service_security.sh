#!/usr/bin/env bash
# navd.service's sandbox: the unit as installed (navd.service.in with a /usr prefix) must score at
# most MAX (default 2.0) in `systemd-analyze security --offline=yes` (issue 40: 8.3 EXPOSED), and
# must still reach what navd opens: the serial devices and ptys (DeviceAllow), CAN and AF_UNIX
# sockets, and no capability it would need (it needs none).
# Usage: navd_service_security.sh SOURCE_DIR [MAX]
set -euo pipefail
src=$1
max=${2:-2.0}
command -v systemd-analyze >/dev/null || { echo "SKIP: systemd-analyze not found (package systemd)"; exit 77; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
sed -e 's|@HIL_NAVD_BINDIR@|/usr/bin|' -e 's|@HIL_NAVD_SYSCONFDIR@|/etc|' \
  "$src/estimator/navd/navd.service.in" >"$tmp/navd.service"
out=$(systemd-analyze security --offline=yes --no-pager "$tmp/navd.service" 2>&1)
level=$(sed -n 's/.*Overall exposure level for navd.service: \([0-9.]*\).*/\1/p' <<<"$out")
[[ -n $level ]] || { echo "no exposure level in:"; echo "$out"; exit 1; }
echo "navd.service exposure $level (at most $max)"
awk -v l="$level" -v m="$max" 'BEGIN { exit !(l <= m) }' || { echo "$out"; exit 1; }
# what navd needs must still be allowed
for need in 'DeviceAllow=char-ttyS rw' 'DeviceAllow=char-ttyUSB rw' 'DeviceAllow=char-ttyACM rw' \
  'DeviceAllow=char-pts rw' 'SupplementaryGroups=dialout'; do
  grep -qx "$need" "$tmp/navd.service" || { echo "navd.service lacks '$need'"; exit 1; }
done
grep -q '^RestrictAddressFamilies=.*AF_CAN' "$tmp/navd.service" || { echo "navd.service forbids AF_CAN"; exit 1; }
echo "navd_service_security: pass"
