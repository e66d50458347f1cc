#!/usr/bin/env python3
"""Independent check of the MCU golden vectors: a second decoder, written in Python from
vectors/mcu/mcu_frame_protocol.md and vectors/can/README.md alone, reads every vector and compares
it with its .expected.csv (within one LSB). Usage: check_mcu_vectors.py SOURCE_DIR"""
import re
import struct
import sys

LENGTHS = {1: 12, 2: 6, 3: 7, 4: 26}


def crc16_ccitt_false(data):
    crc = 0xFFFF
    for byte in data:
        crc ^= byte << 8
        for _ in range(8):
            crc = ((crc << 1) ^ 0x1021) & 0xFFFF if crc & 0x8000 else (crc << 1) & 0xFFFF
    return crc


def expected_rows(path):
    return [line.strip().split(",") for line in open(path) if not line.startswith("#")]


def check_binary(src, name):
    data = open(f"{src}/vectors/mcu/{name}.bin", "rb").read()
    rows = {int(r[0]): r for r in expected_rows(f"{src}/vectors/mcu/{name}.expected.csv")}
    good_rows = sum(1 for r in rows.values() if r[4] == "1")
    i, decoded, scales = 0, 0, None
    while i + 1 < len(data):
        if data[i] != 0xA5 or data[i + 1] != 0x5A:
            i += 1
            continue
        version, mtype, length = data[i + 2], data[i + 3], data[i + 4]
        if version != 1 or LENGTHS.get(mtype) != length or i + 13 + length > len(data):
            i += 1
            continue
        body = data[i + 2:i + 11 + length]
        (crc,) = struct.unpack("<H", data[i + 11 + length:i + 13 + length])
        if crc != crc16_ccitt_false(body):
            i += 1
            continue
        seq, tick = struct.unpack("<HI", data[i + 5:i + 11])
        payload = data[i + 11:i + 11 + length]
        row = rows[i]
        assert (int(row[1]), int(row[2]), int(row[3]), row[4]) == (seq, mtype, tick, "1"), (name, i, row)
        if mtype == 4:
            scales = struct.unpack("<3f", payload[12:24])
        elif mtype in (1, 2):
            counts = struct.unpack(f"<{length // 2}h", payload)
            lsb = [scales[0]] * 3 + [scales[1]] * 3 if mtype == 1 else [scales[2]] * 3
            for k, c in enumerate(counts):
                assert abs(c * lsb[k] - float(row[5 + k])) <= lsb[k], (name, i, k)
        elif mtype == 3:
            week, tow_ms, flags = struct.unpack("<HIB", payload)
            assert [week, tow_ms, flags] == [int(x) for x in row[5:8]], (name, i)
        decoded += 1
        i += 13 + length
    assert decoded == good_rows, (name, decoded, good_rows)
    print(f"{name}: {decoded} frames decoded and matched")


def check_text(src, name):
    lines = open(f"{src}/vectors/mcu/{name}.txt", "rb").read().decode().replace("\n\r", "\n").splitlines()
    rows = expected_rows(f"{src}/vectors/mcu/{name}.expected.csv")
    assert len(lines) == len(rows)
    line_re = re.compile(r"^(?:\$,|!Data:)((?:-?\d+,){8}-?\d+),?#\r?$")
    lsb = [9.80665 / 256] * 3 + [3.3 / 1024 / 3.33e-3 * 3.141592653589793 / 180] * 3 + [100 / 1300] * 3
    for line, row in zip(lines, rows):
        m = line_re.match(line)
        assert m, line
        n = [int(x) for x in m.group(1).split(",")]
        for k in range(9):
            value = (n[k] - 382) * lsb[k] if 3 <= k < 6 else n[k] * lsb[k]
            assert abs(value - float(row[k])) <= lsb[k], (name, line, k)
    print(f"{name}: {len(lines)} lines matched")


def check_can(src):
    lines = open(f"{src}/vectors/can/mcu_j1939.candump").read().splitlines()
    rows = expected_rows(f"{src}/vectors/can/mcu_j1939.expected.csv")
    assert len(lines) == len(rows)
    line_re = re.compile(r"^\((\d{10})\.(\d{6})\) vcan0 ([0-9A-F]{8})#([0-9A-F]{16})$")
    for line, row in zip(lines, rows):
        m = line_re.match(line)
        assert m, line
        d = bytes.fromhex(m.group(4))
        pgn = (int(m.group(3), 16) >> 8) & 0x3FFFF
        assert row[0] == f"{m.group(1)}.{m.group(2)}" and row[1] == m.group(3) and int(row[2]) == pgn
        u16 = lambda a: d[a] | d[a + 1] << 8
        u24 = lambda a: d[a] | d[a + 1] << 8 | d[a + 2] << 16
        if pgn == 61482:
            values, lsb = [u16(k) / 128 - 250 for k in (0, 2, 4)], 1 / 128
        elif pgn == 61485:
            values, lsb = [u16(k) * 0.01 - 320 for k in (0, 2, 4)], 0.01
        elif pgn == 61481:
            values, lsb = [u24(k) / 32768 - 250 for k in (0, 3)], 1 / 32768
        elif pgn == 65360:
            hi = int.from_bytes(d[4:], "little")
            assert [int.from_bytes(d[:4], "little"), hi & 0xFFFFF, hi >> 20] == [int(x) for x in row[3:6]]
            continue
        else:
            raise AssertionError(f"unexpected PGN {pgn}")
        for k, v in enumerate(values):
            assert abs(v - float(row[3 + k])) <= lsb, (line, k)
        assert d[7] * 0.5 == float(row[3 + len(values)])
    print(f"mcu_j1939: {len(lines)} CAN frames matched")


def load_dbc(path):
    """Messages of a DBC file: {frame id with bit 31: (name, [(signal, start, length, signed, scale, offset)])}."""
    messages, current = {}, None
    bo = re.compile(r"^BO_ (\d+) (\w+): (\d+) (\w+)")
    sg = re.compile(r"^ SG_ (\w+) : (\d+)\|(\d+)@1([+-]) \(([^,]+),([^)]+)\)")
    for line in open(path):
        if m := bo.match(line):
            current = messages.setdefault(int(m.group(1)), (m.group(2), []))
        elif (m := sg.match(line)) and current is not None:
            current[1].append((m.group(1), int(m.group(2)), int(m.group(3)), m.group(4) == "-",
                               float(m.group(5)), float(m.group(6))))
    return messages


def check_can_with_dbc(src):
    """Decodes the CAN vector with the DBC's own signal definitions (Intel byte order)."""
    dbc = load_dbc(f"{src}/vectors/can/hil_imu.dbc")
    columns = {
        "ARI": ["PitchRate", "RollRate", "YawRate", "AngularRateLatency"],
        "ACCS": ["LateralAcceleration", "LongitudinalAcceleration", "VerticalAcceleration", "AccelerationLatency"],
        "SSI2": ["PitchAngleExtRange", "RollAngleExtRange", "RollPitchLatency"],
        "HIL_TIME_PULSE": ["PulseTick", "GpsTowSeconds", "GpsWeekMod4096"],
    }
    lines = open(f"{src}/vectors/can/mcu_j1939.candump").read().splitlines()
    rows = expected_rows(f"{src}/vectors/can/mcu_j1939.expected.csv")
    for line, row in zip(lines, rows):
        ident, data = line.split()[2].split("#")
        name, signals = dbc[int(ident, 16) | 0x80000000]
        raw = int.from_bytes(bytes.fromhex(data), "little")
        by_name = {}
        for sig, start, length, signed, scale, offset in signals:
            v = (raw >> start) & ((1 << length) - 1)
            if signed and v >> (length - 1):
                v -= 1 << length
            by_name[sig] = (v * scale + offset, scale)
        for k, sig in enumerate(columns[name]):
            value, scale = by_name[sig]
            assert abs(value - float(row[3 + k])) <= abs(scale), (line, sig, value, row[3 + k])
    print(f"mcu_j1939: {len(lines)} CAN frames decoded with hil_imu.dbc and matched")


if __name__ == "__main__":
    source = sys.argv[1]
    for vector in ("razor_v13_binary", "razor_v13_faults", "tactical_100hz_binary"):
        check_binary(source, vector)
    for vector in ("razor_v13_raw", "razor_v13_v19"):
        check_text(source, vector)
    check_can(source)
    check_can_with_dbc(source)
