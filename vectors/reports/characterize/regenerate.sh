#!/usr/bin/env bash
# Regenerates this folder's figures: hil characterize on walk_0827's still period and on each
# profile's emulated four-hour still log (scenarios/still_<profile>.yaml), with the references
# drawn on the plots. Usage, from the checkout: vectors/reports/characterize/regenerate.sh [HIL]
#   HIL            the hil binary (default build-ci/bin/hil)
#   ALLANTOOLS_DIR (environment) a checkout of aewallin/allantools: also compare every curve with
#                  its oadev (check_allantools.py; Debian's python3-numpy and python3-scipy)
# The runs and the analysed samples go to runs/characterize/ (not kept: 130 MB captures).
set -euo pipefail
hil=${1:-build-ci/bin/hil}
here=vectors/reports/characterize
work=runs/characterize
real=../shared/vectors/real_imu/walk_0827/imu_1730.csv
mkdir -p "$work"

check() {  # $1 name: the allantools comparison of $here/$1/characterize.json
  if [ -n "${ALLANTOOLS_DIR:-}" ]; then
    /usr/bin/python3 "$here/check_allantools.py" "$ALLANTOOLS_DIR" "$here/$1/characterize.json" \
      "$work/$1.samples.csv" | tee "$here/$1/allantools_check.txt"
  fi
}

# the real log: the longest still period (the person standing at the end of the walk)
# ICM-45686 figures: gyro 3.8 mdps/rt-Hz = 0.228 deg/rt-h, accel 70 ug/rt-Hz = 0.0412 m/s/rt-h
if [ -f "$real" ]; then
  "$hil" characterize "$real" --still --json "$here/walk_0827/characterize.json" \
    --svg "$here/walk_0827" --samples-csv "$work/walk_0827.samples.csv" \
    --reference-arw 0.228 --reference-vrw 0.0412 --reference-label "ICM-45686 data sheet" \
    | tee "$here/walk_0827/summary.txt"
  check walk_0827
fi

# the profiles' figures (firmware_emu/src/mcu/sensor_spec.cc): ARW deg/rt-h, gyro bias instability
# deg/h, VRW m/s/rt-h (x axis where the axes differ), accelerometer bias instability m/s^2
declare -A refs=(
  [razor-v13]="--reference-arw 2.1 --reference-gyro-bi 100 --reference-vrw 0.1706 --reference-accel-bi 9.81e-4"
  [consumer-mems]="--reference-arw 0.3 --reference-gyro-bi 4.6 --reference-vrw 0.2354 --reference-accel-bi 3.53e-4"
  [industrial-mems]="--reference-arw 0.15 --reference-gyro-bi 2 --reference-vrw 0.012 --reference-accel-bi 3.53e-5"
)
for p in razor-v13 consumer-mems industrial-mems; do
  "$hil" run "$here/scenarios/still_$p.yaml" --out "$work/still_$p" --nice 0 >/dev/null
  # shellcheck disable=SC2086
  "$hil" characterize "$work/still_$p/captures/ttyIMU.cap" --json "$here/still_$p/characterize.json" \
    --svg "$here/still_$p" --samples-csv "$work/still_$p.samples.csv" ${refs[$p]} \
    --reference-label "profile $p" | tee "$here/still_$p/summary.txt"
  check "still_$p"
done
