#!/usr/bin/python3
"""Example estimator for hil: a GNSS-only constant-velocity Kalman filter (examples/README.md).

Reads the emulated receiver's NMEA 0183 (RMC for the date, GGA for the fix) from its serial link,
filters each local axis (east, north, up) with a constant-velocity Kalman filter, and writes one
JSON object a line on stdout: hil's `json_stdout` output contract (vectors/scenarios/README.md,
"The estimator under test"). The estimate describes the antenna: run it with
`estimator.reference_point: antenna`. Python 3 standard library only.

Usage: gnss_estimator.py --gnss TTY [--baud 9600] [--accel-psd M2/S3] [--fix-std-m M]
                         [--fix-vertical-std-m M]
"""
import argparse
import calendar
import json
import math
import os
import sys
import termios
import tty

WGS84_A = 6378137.0
WGS84_E2 = 6.69437999014e-3


def ecef(lat_deg, lon_deg, h_m):
    lat, lon = math.radians(lat_deg), math.radians(lon_deg)
    n = WGS84_A / math.sqrt(1.0 - WGS84_E2 * math.sin(lat) ** 2)
    return ((n + h_m) * math.cos(lat) * math.cos(lon), (n + h_m) * math.cos(lat) * math.sin(lon),
            (n * (1.0 - WGS84_E2) + h_m) * math.sin(lat))


class LocalFrame:
    """East-north-up metres about a geodetic origin (WGS84), and back."""

    def __init__(self, lat_deg, lon_deg, h_m):
        self.origin = (lat_deg, lon_deg, h_m)
        self.o = ecef(lat_deg, lon_deg, h_m)
        lat, lon = math.radians(lat_deg), math.radians(lon_deg)
        sl, cl, so, co = math.sin(lat), math.cos(lat), math.sin(lon), math.cos(lon)
        self.r = ((-so, co, 0.0), (-sl * co, -sl * so, cl), (cl * co, cl * so, sl))

    def to_enu(self, lat_deg, lon_deg, h_m):
        p = ecef(lat_deg, lon_deg, h_m)
        d = [p[i] - self.o[i] for i in range(3)]
        return [sum(self.r[k][i] * d[i] for i in range(3)) for k in range(3)]

    def to_lla(self, enu):
        # ENU -> ECEF, then Bowring-free fixed-point latitude (converges to < 1e-9 rad in 5 turns)
        x = [self.o[i] + sum(self.r[k][i] * enu[k] for k in range(3)) for i in range(3)]
        lon = math.atan2(x[1], x[0])
        p = math.hypot(x[0], x[1])
        lat = math.atan2(x[2], p * (1.0 - WGS84_E2))
        for _ in range(5):
            n = WGS84_A / math.sqrt(1.0 - WGS84_E2 * math.sin(lat) ** 2)
            h = p / math.cos(lat) - n
            lat = math.atan2(x[2], p * (1.0 - WGS84_E2 * n / (n + h)))
        n = WGS84_A / math.sqrt(1.0 - WGS84_E2 * math.sin(lat) ** 2)
        return math.degrees(lat), math.degrees(lon), p / math.cos(lat) - n


class AxisFilter:
    """Constant-velocity Kalman filter of one axis: state (position, velocity)."""

    def __init__(self, accel_psd, pos, pos_var):
        self.q = accel_psd
        self.x = [pos, 0.0]
        self.p = [[pos_var, 0.0], [0.0, 4.0]]  # velocity unknown: 2 m/s (1 sigma) at the start

    def predict(self, dt):
        p, q = self.p, self.q
        self.x[0] += dt * self.x[1]
        p00 = p[0][0] + dt * (p[0][1] + p[1][0]) + dt * dt * p[1][1] + q * dt ** 3 / 3.0
        p01 = p[0][1] + dt * p[1][1] + q * dt * dt / 2.0
        self.p = [[p00, p01], [p01, p[1][1] + q * dt]]

    def update(self, z, r):
        s = self.p[0][0] + r
        k0, k1 = self.p[0][0] / s, self.p[1][0] / s
        y = z - self.x[0]
        self.x = [self.x[0] + k0 * y, self.x[1] + k1 * y]
        p = self.p
        self.p = [[(1 - k0) * p[0][0], (1 - k0) * p[0][1]],
                  [p[1][0] - k1 * p[0][0], p[1][1] - k1 * p[0][1]]]


def checksum_ok(line):
    star = line.rfind("*")
    if not line.startswith("$") or star < 0 or len(line) < star + 3:
        return False
    x = 0
    for c in line[1:star]:
        x ^= ord(c)
    try:
        return int(line[star + 1:star + 3], 16) == x
    except ValueError:
        return False


def degrees(value, hemisphere, width):
    """NMEA ddmm.mmmm / dddmm.mmmm to signed degrees."""
    d = int(value[:width]) + float(value[width:]) / 60.0
    return -d if hemisphere in ("S", "W") else d


def seconds_of_day(hhmmss):
    return int(hhmmss[0:2]) * 3600 + int(hhmmss[2:4]) * 60 + float(hhmmss[4:])


class Estimator:
    def __init__(self, args, out):
        self.args, self.out = args, out
        self.date_utc_s = None  # midnight UTC of the RMC's date, Unix seconds
        self.frame, self.axes, self.t_s = None, None, None

    def on_sentence(self, line):
        f = line[1:line.rfind("*")].split(",")
        kind = f[0][2:]
        if kind == "RMC" and len(f) >= 10 and f[9]:
            d = f[9]
            self.date_utc_s = calendar.timegm((2000 + int(d[4:6]), int(d[2:4]), int(d[0:2]), 0, 0, 0))
        elif kind == "GGA" and len(f) >= 12 and f[6] not in ("", "0") and f[2] and f[4]:
            if self.date_utc_s is None:
                return  # no date yet: no time of validity
            t = self.date_utc_s + seconds_of_day(f[1])
            h = float(f[9] or 0.0) + float(f[11] or 0.0)  # ellipsoidal = MSL altitude + separation
            hdop = float(f[8]) if f[8] else 1.0
            self.on_fix(t, degrees(f[2], f[3], 2), degrees(f[4], f[5], 3), h, hdop)

    def on_fix(self, t, lat, lon, h, hdop):
        a = self.args
        r_h, r_v = (a.fix_std_m * hdop) ** 2, (a.fix_vertical_std_m * hdop) ** 2
        if self.frame is None:
            self.frame = LocalFrame(lat, lon, h)
            self.axes = [AxisFilter(a.accel_psd, 0.0, v) for v in (r_h, r_h, r_v)]
        else:
            dt = t - self.t_s
            if dt <= 0:
                return  # a repeated or older epoch
            for k, z in enumerate(self.frame.to_enu(lat, lon, h)):
                self.axes[k].predict(dt)
                self.axes[k].update(z, r_v if k == 2 else r_h)
        self.t_s = t
        self.write(t)

    def write(self, t):
        pos = [ax.x[0] for ax in self.axes]
        vel = [ax.x[1] for ax in self.axes]
        lat, lon, h = self.frame.to_lla(pos)
        sol = {
            "tov_unix_ns": int(round(t * 1e9)),
            "lat_deg": round(lat, 9), "lon_deg": round(lon, 9), "height_m": round(h, 4),
            "vel_enu_mps": [round(v, 4) for v in vel],
            "pos_std_enu_m": [round(math.sqrt(ax.p[0][0]), 4) for ax in self.axes],
        }
        self.out.write(json.dumps(sol) + "\n")
        self.out.flush()


def open_serial(path, baud):
    fd = os.open(path, os.O_RDONLY | os.O_NOCTTY)
    try:
        attrs = termios.tcgetattr(fd)
        speed = getattr(termios, "B%d" % baud)
        attrs[4] = attrs[5] = speed
        termios.tcsetattr(fd, termios.TCSANOW, attrs)
        tty.setraw(fd)
    except termios.error:
        pass  # not a terminal (a file replayed for a test): read it as it is
    return fd


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--gnss", required=True, help="the receiver's serial link ({ttyGPS})")
    ap.add_argument("--baud", type=int, default=9600)
    ap.add_argument("--accel-psd", type=float, default=0.01,
                    help="white acceleration PSD per axis, m^2/s^3 (our choice: a vehicle at a "
                         "steady field speed)")
    ap.add_argument("--fix-std-m", type=float, default=0.5,
                    help="horizontal fix error per axis at HDOP 1, m (our choice: a standalone "
                         "u-blox 5 class receiver)")
    ap.add_argument("--fix-vertical-std-m", type=float, default=1.5,
                    help="vertical fix error at HDOP 1, m (our choice)")
    args = ap.parse_args()
    if args.baud <= 0 or not hasattr(termios, "B%d" % args.baud):
        ap.error("--baud: not a serial line rate: %d" % args.baud)
    try:
        fd = open_serial(args.gnss, args.baud)
    except OSError as e:
        print("gnss_estimator: cannot open %s: %s" % (args.gnss, e), file=sys.stderr)
        return 1
    est, pending = Estimator(args, sys.stdout), b""
    while True:
        try:
            chunk = os.read(fd, 4096)
        except OSError:
            chunk = b""  # EIO: the pty's other side closed (the run ended)
        if not chunk:
            return 0
        pending += chunk
        *lines, pending = pending.split(b"\n")
        for raw in lines:
            line = raw.decode("ascii", "replace").strip()
            if checksum_ok(line):
                est.on_sentence(line)


if __name__ == "__main__":
    sys.exit(main())
