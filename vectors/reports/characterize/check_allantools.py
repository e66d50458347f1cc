#!/usr/bin/python3
"""Compares hil characterize's overlapping Allan deviation with allantools' oadev.

Usage: check_allantools.py ALLANTOOLS_DIR RESULT.json SAMPLES.csv
  ALLANTOOLS_DIR  a checkout of github.com/aewallin/allantools (outside the project; it needs
                  Debian's python3-numpy and python3-scipy)
  RESULT.json     `hil characterize ... --json`, SAMPLES.csv its `--samples-csv`
Prints the largest relative difference per sensor and axis over every tau; exits 1 above 2 %.
"""
import csv
import json
import sys

sys.path.insert(0, sys.argv[1])
import allantools  # noqa: E402  (a third-party judge, loaded from the given folder)

result = json.load(open(sys.argv[2]))
cols = {k: [] for k in ("gx_radps", "gy_radps", "gz_radps", "ax_mps2", "ay_mps2", "az_mps2")}
for row in csv.DictReader(open(sys.argv[3])):
    for k in cols:
        cols[k].append(float(row[k]))
rate = 1.0 / result["step_s"]
worst = 0.0
for sensor, key in (("g", "allan_gyro_radps"), ("a", "allan_accel_mps2")):
    for axis in "xyz":
        name = next(k for k in cols if k.startswith(sensor + axis))
        taus, adev, _, _ = allantools.oadev(cols[name], rate=rate, data_type="freq",
                                            taus=result["tau_s"])
        ours = dict(zip(result["tau_s"], result[key][axis]))
        diffs = [abs(ours[t] / d - 1) for t, d in zip(taus, adev)]
        worst = max(worst, max(diffs))
        print(f"{key}.{axis}: {len(diffs)} tau, max |ours/allantools - 1| = {max(diffs):.2e}")
print(f"allantools {allantools.__version__}: worst relative difference {worst:.2e}")
sys.exit(0 if worst <= 0.02 else 1)
