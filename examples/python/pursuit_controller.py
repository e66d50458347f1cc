#!/usr/bin/python3
"""Example controller for hil: pure pursuit of a differential-drive base (examples/README.md).

Reads the navigation solution as NMEA 0183 (RMC, GGA, HDT once per solution, navd's
`[output] nmea_device`: the FIFO {nav_nmea}) and a planned-path file (`hil-path 1`: ab_line or
polyline), and at each solution (its HDT) sends one wheel-speed command `m <L> <R>` to the base
over the ROSArduinoBridge serial protocol (57600 8N1, vectors/base_serial/README.md), reading and
dropping its replies: the contract of estimator/guidanced/README.md. Python 3 standard library
only.

Usage: pursuit_controller.py --path FILE --origin LAT,LON,H --nav NMEA_IN --base TTY
           [--speed 0.5] [--lookahead 1.0] [--track 0.5] [--wheel-radius 0.1]
           [--counts-per-rev 1200] [--pid-rate 30]
"""
import argparse
import math
import os
import select
import sys
import termios
import tty

WGS84_A = 6378137.0
WGS84_E2 = 6.69437999014e-3


class PathError(Exception):
    pass


def ecef(lat_deg, lon_deg, h_m):
    lat, lon = math.radians(lat_deg), math.radians(lon_deg)
    n = WGS84_A / math.sqrt(1.0 - WGS84_E2 * math.sin(lat) ** 2)
    return ((n + h_m) * math.cos(lat) * math.cos(lon), (n + h_m) * math.cos(lat) * math.sin(lon),
            (n * (1.0 - WGS84_E2) + h_m) * math.sin(lat))


def east_north(origin, lat_deg, lon_deg, h_m):
    """East and north metres of a geodetic point from the origin (lat, lon, h), WGS84."""
    o, p = ecef(*origin), ecef(lat_deg, lon_deg, h_m)
    d = [p[i] - o[i] for i in range(3)]
    lat, lon = math.radians(origin[0]), math.radians(origin[1])
    sl, cl, so, co = math.sin(lat), math.cos(lat), math.sin(lon), math.cos(lon)
    return (-so * d[0] + co * d[1], -sl * co * d[0] - sl * so * d[1] + cl * d[2])


def point(path, line_no, field, value):
    try:
        e, n = (float(v) for v in value.split(","))
    except ValueError:
        raise PathError("%s:%d: field '%s': expected E,N in metres: '%s'" % (path, line_no, field, value))
    return (e, n)


def read_path(path):
    """The vertices of an ab_line or polyline path file (vectors/paths/README.md)."""
    try:
        with open(path, encoding="ascii") as f:
            lines = [(i + 1, l.split("#")[0].split()) for i, l in enumerate(f)]
    except (OSError, UnicodeDecodeError) as e:
        raise PathError("%s: cannot read: %s" % (path, e))
    lines = [(i, w) for i, w in lines if w]
    if not lines or lines[0][1] != ["hil-path", "1"]:
        raise PathError("%s:%d: expected the header 'hil-path 1'" % (path, lines[0][0] if lines else 1))
    if len(lines) < 2:
        raise PathError("%s: no shape after the header" % path)
    no, words = lines[1]
    fields = dict(w.split("=", 1) for w in words[1:] if "=" in w)
    if words[0] == "ab_line":
        for key in ("a_m", "b_m"):
            if key not in fields:
                raise PathError("%s:%d: field '%s' missing" % (path, no, key))
        a, b = point(path, no, "a_m", fields["a_m"]), point(path, no, "b_m", fields["b_m"])
        ext = float(fields.get("extend_m", "0"))
        length = math.hypot(b[0] - a[0], b[1] - a[1])
        if length == 0:
            raise PathError("%s:%d: field 'b_m': A and B are the same point" % (path, no))
        u = ((b[0] - a[0]) / length, (b[1] - a[1]) / length)
        return [a, (b[0] + ext * u[0], b[1] + ext * u[1])]
    if words[0] == "polyline":
        vertices = []
        for no, words in lines[2:]:
            if words[0] != "vertex" or not words[1:] or not words[1].startswith("p_m="):
                raise PathError("%s:%d: expected 'vertex p_m=E,N'" % (path, no))
            vertices.append(point(path, no, "p_m", words[1][4:]))
        if len(vertices) < 2:
            raise PathError("%s: a polyline needs at least 2 vertices" % path)
        return vertices
    raise PathError("%s:%d: shape '%s': this example reads ab_line and polyline only"
                    % (path, no, words[0]))


class PurePursuit:
    """Pure pursuit along a polyline; progress only moves forward."""

    def __init__(self, vertices, lookahead_m):
        self.v, self.lookahead = vertices, lookahead_m
        self.seg = 0

    def closest(self, p):
        """Segment index and fraction of the point nearest p, searching from the current one."""
        best = None
        for i in range(self.seg, len(self.v) - 1):
            (ax, ay), (bx, by) = self.v[i], self.v[i + 1]
            dx, dy = bx - ax, by - ay
            f = max(0.0, min(1.0, ((p[0] - ax) * dx + (p[1] - ay) * dy) / (dx * dx + dy * dy)))
            d = math.hypot(ax + f * dx - p[0], ay + f * dy - p[1])
            if best is None or d < best[0]:
                best = (d, i, f)
        return best[1], best[2]

    def target(self, i, f):
        """The point lookahead metres along the path from segment i at fraction f (or its end)."""
        left = self.lookahead
        while True:
            (ax, ay), (bx, by) = self.v[i], self.v[i + 1]
            seg_len = math.hypot(bx - ax, by - ay)
            rest = (1.0 - f) * seg_len
            if left <= rest or i == len(self.v) - 2:
                g = min(1.0, f + left / seg_len)
                return (ax + g * (bx - ax), ay + g * (by - ay)), left > rest
            left -= rest
            i, f = i + 1, 0.0

    def update(self, p, yaw_rad):
        """Curvature (1/m, positive left) and whether the path has ended."""
        self.seg, f = self.closest(p)
        (tx, ty), beyond = self.target(self.seg, f)
        dist = math.hypot(tx - p[0], ty - p[1])
        if beyond and dist < 0.5 * self.lookahead:
            return 0.0, True  # the end of the path is closer than half the look-ahead
        alpha = math.atan2(ty - p[1], tx - p[0]) - yaw_rad
        return 2.0 * math.sin(alpha) / max(dist, 1e-6), False


def nmea_fields(line):
    star = line.rfind("*")
    if not line.startswith("$") or star < 0:
        return None
    x = 0
    for c in line[1:star]:
        x ^= ord(c)
    try:
        if int(line[star + 1:star + 3], 16) != x:
            return None
    except ValueError:
        return None
    return line[1:star].split(",")


def degrees(value, hemisphere, width):
    d = int(value[:width]) + float(value[width:]) / 60.0
    return -d if hemisphere in ("S", "W") else d


class Controller:
    def __init__(self, args, vertices, base_fd):
        self.a, self.base_fd = args, base_fd
        self.pursuit = PurePursuit(vertices, args.lookahead)
        self.p = None  # east, north of the last GGA
        self.commands = 0

    def on_sentence(self, line):
        f = nmea_fields(line)
        if not f or len(f[0]) < 5:
            return
        kind = f[0][2:]
        if kind == "GGA" and len(f) >= 12 and f[6] not in ("", "0") and f[2] and f[4]:
            h = float(f[9] or 0.0) + float(f[11] or 0.0)
            self.p = east_north(self.a.origin, degrees(f[2], f[3], 2), degrees(f[4], f[5], 3), h)
        elif kind == "HDT" and len(f) >= 2 and f[1] and self.p is not None:
            self.command(math.radians(90.0 - float(f[1])))  # compass heading to ENU yaw

    def command(self, yaw_rad):
        a = self.a
        kappa, ended = self.pursuit.update(self.p, yaw_rad)
        v = 0.0 if ended else a.speed
        ticks = []
        for side in (-1.0, 1.0):  # left, right wheel
            wheel_radps = v * (1.0 + side * kappa * a.track / 2.0) / a.wheel_radius
            ticks.append(int(round(wheel_radps / (2.0 * math.pi) * a.counts_per_rev / a.pid_rate)))
        os.write(self.base_fd, b"m %d %d\r" % (ticks[0], ticks[1]))
        self.commands += 1


def open_base(path):
    fd = os.open(path, os.O_RDWR | os.O_NOCTTY)
    try:
        attrs = termios.tcgetattr(fd)
        attrs[4] = attrs[5] = termios.B57600
        termios.tcsetattr(fd, termios.TCSANOW, attrs)
        tty.setraw(fd)
    except termios.error:
        pass
    return fd


def parse_args():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--path", required=True)
    ap.add_argument("--origin", required=True, help="LAT,LON,H: the scenario's origin ({origin})")
    ap.add_argument("--nav", required=True, help="the solution's NMEA ({nav_nmea})")
    ap.add_argument("--base", required=True, help="the base's serial link ({ttyBASE})")
    ap.add_argument("--speed", type=float, default=0.5, help="m/s")
    ap.add_argument("--lookahead", type=float, default=1.0, help="m")
    ap.add_argument("--track", type=float, default=0.5, help="m, between the wheels")
    ap.add_argument("--wheel-radius", type=float, default=0.1, help="m")
    ap.add_argument("--counts-per-rev", type=int, default=1200)
    ap.add_argument("--pid-rate", type=float, default=30.0, help="the base's PID frames per second")
    a = ap.parse_args()
    try:
        a.origin = tuple(float(x) for x in a.origin.split(","))
        if len(a.origin) != 3:
            raise ValueError
    except ValueError:
        ap.error("--origin: expected LAT,LON,H")
    if a.lookahead <= 0 or a.wheel_radius <= 0 or a.pid_rate <= 0 or a.counts_per_rev <= 0:
        ap.error("--lookahead, --wheel-radius, --pid-rate and --counts-per-rev must be positive")
    return a


def main():
    a = parse_args()
    try:
        vertices = read_path(a.path)
    except PathError as e:
        print("pursuit_controller: %s" % e, file=sys.stderr)
        return 2
    try:
        base_fd = open_base(a.base)
        nav_fd = os.open(a.nav, os.O_RDONLY)
    except OSError as e:
        print("pursuit_controller: %s" % e, file=sys.stderr)
        return 1
    ctl, pending = Controller(a, vertices, base_fd), b""
    while True:
        readable, _, _ = select.select([nav_fd, base_fd], [], [])
        if base_fd in readable:
            try:
                if not os.read(base_fd, 4096):  # the base's "OK" replies: read and dropped
                    break
            except OSError:
                break  # the base's port closed
        if nav_fd in readable:
            chunk = os.read(nav_fd, 4096)
            if not chunk:
                break  # the estimator's output ended
            pending += chunk
            *lines, pending = pending.split(b"\n")
            for raw in lines:
                ctl.on_sentence(raw.decode("ascii", "replace").strip())
    print("pursuit_controller: stopped; commands=%d" % ctl.commands, file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
