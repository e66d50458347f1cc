#!/usr/bin/env bash
# ctest label slurm: a real one-node Slurm cluster (ci/slurm/slurm-up) in a temporary folder runs a
# small campaign (2 scenarios × 8 seeds, short forms) as 4 array tasks plus the afterok merge job,
# and the merged outputs must be byte for byte those of `hil campaign --local -j 2`. Every daemon
# is stopped by its PID (ci/slurm/slurm-down) and the test fails if any process of the cluster is
# left. When Slurm cannot start, the test FAILS: it never passes or skips silently.
# Usage: slurm_campaign_test.sh HIL SOURCE_DIR
set -uo pipefail
hil=${1:?usage: slurm_campaign_test.sh HIL SOURCE_DIR}
src=${2:?usage: slurm_campaign_test.sh HIL SOURCE_DIR}
work=$(mktemp -d /tmp/hil_slurm_test_XXXXXX)
chmod 755 "$work"  # munged wants every folder above its socket executable by all
cluster=$work/cluster
conf=$cluster/etc/slurm.conf
status=0
fail() { echo "FAIL: $*"; status=1; }
since() { awk -v a="$1" -v b="$(date +%s.%N)" 'BEGIN { printf "%.2f", b - a }'; }

leftovers() {  # processes that carry this cluster's SLURM_CONF (daemons, jobs, their runs)
  local p
  for p in /proc/[0-9]*; do
    [ "${p#/proc/}" = "$$" ] && continue
    { tr '\0' '\n' <"$p/environ"; } 2>/dev/null | grep -qx "SLURM_CONF=$conf" && echo "${p#/proc/}"
  done
}

cleanup() {
  "$src/ci/slurm/slurm-down" "$cluster" || fail "slurm-down could not stop every daemon"
  local left
  left=$(leftovers)
  if [ -n "$left" ]; then
    fail "processes left behind: $left"
    for p in $left; do echo "  $p: $(tr '\0' ' ' <"/proc/$p/cmdline" 2>/dev/null)"; done
  fi
  if [ $status -eq 0 ]; then rm -rf "$work"; else echo "kept $work for inspection"; fi
  echo "slurm campaign test: $([ $status -eq 0 ] && echo PASS || echo FAIL)"
  exit $status
}
trap cleanup EXIT

t0=$(date +%s.%N)
if ! "$src/ci/slurm/slurm-up" "$cluster"; then
  fail "Slurm could not start (ci/setup installs slurmctld slurmd slurm-client munge)"
  exit 1
fi
echo "cluster up in $(since "$t0") s"

sc=$src/vectors/scenarios
cat >"$work/mc.yaml" <<YAML
name: slurm-ci
scenarios: [$sc/seed000_gps_only.yaml, $sc/straight_line_outage.yaml]
short: true
seeds: {from: 1, to: 8}
criteria:
  - {metric: horizontal_rmse_m, stat: p95, max: 5.0}
YAML
cd "$work" || exit 1

t0=$(date +%s.%N)
"$hil" campaign mc.yaml --local -j 2 --out local >local.log 2>&1
local_rc=$?
echo "--local -j 2: exit $local_rc in $(since "$t0") s"
[ "$local_rc" -le 1 ] || { cat local.log; fail "--local exited $local_rc"; }

t0=$(date +%s.%N)
SLURM_CONF=$conf "$hil" campaign mc.yaml --slurm --array-tasks 4 --wait --out slurm >slurm.log 2>&1
slurm_rc=$?
wall=$(since "$t0")
cat slurm.log
echo "--slurm (4 array tasks + merge): exit $slurm_rc in $wall s"
[ "$slurm_rc" = "$local_rc" ] || fail "--slurm exited $slurm_rc, --local $local_rc"
grep -q "afterok" slurm/slurm/shards.sbatch slurm.log || fail "no afterok merge job was submitted"
[ -s slurm/slurm/shards.sbatch ] && [ -s slurm/slurm/merge.sbatch ] || fail "sbatch scripts missing"
for k in 1 2 3 4; do
  [ -s "slurm/logs/shard-$k.out" ] || fail "array task $k wrote no log"
done
[ -s slurm/logs/merge.out ] || fail "the merge job wrote no log"
SLURM_CONF=$conf "$hil" campaign status slurm || fail "status: the campaign is not complete"

for f in summary.json report.md report.html junit.xml plots/cdf_horizontal_rmse_m.svg; do
  if [ ! -s "local/$f" ]; then
    fail "--local wrote no $f"
  elif ! cmp -s "local/$f" "slurm/$f"; then
    fail "$f differs between --local and Slurm"
    diff "local/$f" "slurm/$f" | head -20
  fi
done
[ "$(ls slurm/records | wc -l)" = 16 ] || fail "expected 16 run records, found $(ls slurm/records | wc -l)"
