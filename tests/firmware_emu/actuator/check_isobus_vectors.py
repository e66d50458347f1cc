#!/usr/bin/env python3
"""Third, independent judge of vectors/isobus/guidance_golden.txt: decodes every frame with the
signal definitions of vectors/can/hil_imu.dbc (matched on the PGN, as the DBC's comment asks) and
compares the values with the line's key=value expectations. Usage: check_isobus_vectors.py SRC"""
import re
import sys

SIGNALS = {  # golden key -> DBC signal, per message
    "ISOBUS_GuidanceSystemCommand": {"curvature_per_km": "CommandedCurvature", "status": "CurvatureCommandStatus"},
    "ISOBUS_GuidanceMachineInfo": {
        "curvature_per_km": "EstimatedCurvature", "lockout": "MechanicalSystemLockout",
        "readiness": "SteeringSystemReadiness", "input_position": "SteeringInputPositionStatus",
        "reset": "RequestResetCommandStatus", "limit": "GuidanceLimitStatus",
        "exit": "ExitReasonCode", "engage_switch": "RemoteEngageSwitchStatus"},
    "ISOBUS_WheelBasedSpeedDistance": {
        "speed_mps": "WheelBasedSpeed", "distance_m": "WheelBasedDistance",
        "max_time_min": "MaxTimeOfTractorPower", "direction": "MachineDirection",
        "key_switch": "KeySwitchState", "implement_start_stop": "ImplementStartStop",
        "operator_direction_reversed": "OperatorDirectionReversed"},
}


def pgn_of(ident):
    pgn = (ident >> 8) & 0x3FFFF
    return pgn & 0x3FF00 if ((pgn >> 8) & 0xFF) < 240 else pgn


def load_dbc(path):
    """{pgn: (name, {signal: (start, length, scale, offset)})} of the DBC's extended frames."""
    out, current = {}, None
    bo = re.compile(r"^BO_ (\d+) (\w+): (\d+) (\w+)")
    sg = re.compile(r"^ SG_ (\w+) : (\d+)\|(\d+)@1\+ \(([^,]+),([^)]+)\)")
    for line in open(path):
        if m := bo.match(line):
            current = out.setdefault(pgn_of(int(m.group(1)) & 0x1FFFFFFF), (m.group(2), {}))
        elif (m := sg.match(line)) and current is not None:
            current[1][m.group(1)] = (int(m.group(2)), int(m.group(3)), float(m.group(4)), float(m.group(5)))
    return out


def main(src):
    dbc = load_dbc(f"{src}/vectors/can/hil_imu.dbc")
    checked = 0
    for n, line in enumerate(open(f"{src}/vectors/isobus/guidance_golden.txt"), 1):
        if not line.strip() or line.startswith("#"):
            continue
        words = line.split()
        ident, data = words[0].split("#")
        fields = dict(w.split("=", 1) for w in words[1:])
        ident = int(ident, 16)
        assert pgn_of(ident) == int(fields["pgn"]), (n, "pgn")
        assert ident & 0xFF == int(fields["sa"], 0), (n, "sa")
        payload = bytes.fromhex(data)
        if len(payload) != 8:
            assert fields.get("error") == "wrong_length", (n, "length")
            continue
        name, signals = dbc[pgn_of(ident)]
        raw = int.from_bytes(payload, "little")
        if fields.get("error") == "out_of_range":
            start, length, _, _ = signals["CommandedCurvature"]
            assert (raw >> start) & ((1 << length) - 1) > 64255, (n, "expected raw > 64255")
            continue
        for key, sig in SIGNALS[name].items():
            start, length, scale, offset = signals[sig]
            value = ((raw >> start) & ((1 << length) - 1)) * scale + offset
            want = float(fields.get("decoded_per_km", fields[key]) if key == "curvature_per_km" else fields[key])
            assert abs(value - want) <= abs(scale) / 2 + 1e-9, (n, key, value, want)
        checked += 1
    assert checked >= 18, checked
    print(f"isobus guidance: {checked} frames decoded with hil_imu.dbc and matched")


if __name__ == "__main__":
    main(sys.argv[1])
