#!/usr/bin/env python3
"""Independent judge of vectors/wt901c and vectors/uwb/linktrack_tag_frame0.*: parses the bytes
from the protocol descriptions (seeds_001_003.md C.1, C.2.1) with Python's struct module and
compares them with the expected CSVs. Exit 0 when everything agrees."""
import csv
import math
import struct
import sys


def rows(path):
    with open(path, encoding="ascii") as f:
        lines = [l for l in f if not l.startswith("#")]
    return list(csv.DictReader(lines))


def check_wit(root):
    data = open(f"{root}/vectors/wt901c/wt901c_session.bin", "rb").read()
    exp = rows(f"{root}/vectors/wt901c/wt901c_session.expected.csv")
    assert len(data) == 11 * len(exp), "size"
    lsb = {0x51: 16 / 32768, 0x52: 2000 / 32768, 0x53: 180 / 32768, 0x54: 1.0}
    for i, r in enumerate(exp):
        p = data[11 * i:11 * i + 11]
        assert p[0] == 0x55 and sum(p[:10]) & 0xFF == p[10], f"packet {i}: header/sum"
        typ = p[1]
        assert typ == int(r["type"], 16), f"packet {i}: type"
        d = struct.unpack("<4h", p[2:10])
        want = [float(r[f"v{k}"]) for k in range(4)]
        if typ == 0x5F:
            assert [v & 0xFFFF for v in d] == [int(w) for w in want], f"packet {i}: registers"
            continue
        for k in range(3):
            got = d[k] * lsb[typ]
            diff = got - want[k]
            if typ == 0x53:
                diff = math.remainder(diff, 360.0)
                assert -180.0 <= got < 180.0
            assert abs(diff) <= lsb[typ] + 1e-9, f"packet {i} field {k}: {got} vs {want[k]}"
    return len(exp)


def check_linktrack(root):
    data = open(f"{root}/vectors/uwb/linktrack_tag_frame0.bin", "rb").read()
    exp = rows(f"{root}/vectors/uwb/linktrack_tag_frame0.expected.csv")
    assert len(data) == 128 * len(exp)

    def i24(b):
        return int.from_bytes(b, "little", signed=True)

    for i, r in enumerate(exp):
        f = data[128 * i:128 * i + 128]
        assert f[0] == 0x55 and f[1] == 0x01 and sum(f[:127]) & 0xFF == f[127], f"frame {i}"
        pos = [i24(f[4 + 3 * k:7 + 3 * k]) / 1000 for k in range(3)]
        dis = [i24(f[22 + 3 * k:25 + 3 * k]) / 1000 for k in range(4)]
        yaw = struct.unpack("<h", f[86:88])[0] / 100
        sys_ms = struct.unpack("<I", f[112:116])[0]
        volt = struct.unpack("<H", f[120:122])[0] / 1000
        assert sys_ms == int(r["system_time_ms"])
        for k, n in enumerate("xyz"):
            assert abs(pos[k] - float(r[f"{n}_m"])) <= 0.0005 + 1e-9, f"frame {i} pos"
        for k in range(4):
            assert abs(dis[k] - float(r[f"dis{k}_m"])) <= 0.0005 + 1e-9, f"frame {i} dis"
        assert abs(yaw - float(r["yaw_deg"])) <= 0.005 + 1e-9
        assert abs(volt - float(r["voltage_v"])) <= 0.0005 + 1e-9
    return len(exp)


if __name__ == "__main__":
    root = sys.argv[1] if len(sys.argv) > 1 else "."
    n1 = check_wit(root)
    n2 = check_linktrack(root)
    print(f"wt901c: {n1} packets ok; linktrack: {n2} frames ok")
