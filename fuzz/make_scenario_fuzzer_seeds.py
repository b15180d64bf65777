#!/usr/bin/env python3
"""Writes the seed corpus of scenario_fuzzer (fuzz/scenario_fuzzer_seeds/).

The target decodes its bytes with fuzz/byte_scenario.cpp: one byte per choice, two big-endian
bytes per real number (modulo the range's number of grid steps + 1, 0 = the lower bound), in a
fixed order: the road, the parameters, the ego, the vehicle count, then 47 bytes per vehicle.
Short inputs decode to vehicle-free scenes, which is where a fuzzer starting from nothing stays
for a long time; these seeds start it with vehicles of every behaviour and non-compliance, two
and three main lanes, and the ranges' bounds. The ranges are read from fuzz/scenario_spec.h, so
a seed keeps its meaning (nominal, bound) when a range changes: run this again then.

    python3 fuzz/make_scenario_fuzzer_seeds.py    # from the repository root
"""
import pathlib
import random
import re

ROOT = pathlib.Path(__file__).resolve().parent.parent
SPEC = (ROOT / "fuzz" / "scenario_spec.h").read_text()
OUT = ROOT / "fuzz" / "scenario_fuzzer_seeds"

HEADER_BYTES = 52  # everything before the vehicle count
VEHICLE_BYTES = 47


def grid_index(name, how, rng):
    """The two-byte value of range `name` that decodes to its nominal value, a bound or at random."""
    fields = re.search(r"RealRange %s\{([^}]*)\}" % name, SPEC).group(1).split(",")
    lo, hi, nominal, resolution = (float(x) for x in fields)
    steps = round((hi - lo) / resolution)
    value = {"nominal": round((nominal - lo) / resolution), "lo": 0, "hi": steps}.get(how)
    if value is None:
        value = rng.randint(0, steps)
    return bytes([value >> 8, value & 0xFF])


def reals(names, how, rng):
    return b"".join(grid_index(n, how, rng) for n in names)


LIMITS = ["kAccelMax", "kBrakeMin", "kBrakeMaxExtra", "kLatAccelMax", "kLatBrakeMin"]


def header(how, rng, count, main_lanes=1, ego_v2v=1):
    b = grid_index("kLaneWidth", how, rng) + bytes([main_lanes - 1])
    b += reals(["kSideLaneStart", "kSideLaneLength", "kSpeedLimit"], how, rng)
    b += reals(["kResponseTime", "kMergeDuration", "kCommThreshold", "kHorizon"], how, rng)
    b += reals(["kEgoOffset", "kEgoLateralOffset", "kEgoSpeed", "kEgoLength", "kEgoWidth"], how, rng)
    b += reals(LIMITS, how, rng) + bytes([ego_v2v]) + reals(["kEgoLatency", "kEgoLoss"], how, rng)
    b += reals(["kMass", "kCgToFront", "kCgToRear", "kCornering", "kCornering"], how, rng)
    assert len(b) == HEADER_BYTES
    return b + bytes([count])


def vehicle(how, rng, lane, behaviour, noncompliance, v2v=1):
    b = bytes([lane]) + reals(["kFirstOffset", "kGap", "kSpeed", "kLength", "kWidth", "kHeight"], how, rng)
    b += reals(LIMITS, how, rng) + bytes([behaviour])
    b += reals(["kDesiredSpeedDelta", "kHeadway", "kMinGap", "kComfortBrake"], how, rng)
    b += bytes([rng.randint(0, 255)]) + grid_index("kSegment", how, rng)
    b += bytes([v2v]) + reals(["kLatency", "kLoss"], how, rng)
    b += bytes([noncompliance]) + reals(["kNcStart", "kNcDuration", "kNcExcess"], how, rng)
    assert len(b) == VEHICLE_BYTES
    return b


def seeds():
    rng = random.Random(1)
    out = {}
    # The nominal scene with one vehicle of each behaviour, then of each non-compliance.
    for behaviour in range(6):
        out[f"nominal_behaviour{behaviour}"] = header("nominal", rng, 1) + vehicle("nominal", rng, behaviour % 3, behaviour, 0)
    for nc in range(1, 4):
        out[f"nominal_noncompliance{nc}"] = header("nominal", rng, 1) + vehicle("nominal", rng, 0, nc % 6, nc)
    # Crowded nominal scenes: 2 to 6 vehicles over the lanes, one to three main lanes.
    for k in range(2, 7):
        out[f"nominal_{k}_vehicles"] = header("nominal", rng, k, main_lanes=1 + k % 3) + b"".join(
            vehicle("nominal", rng, i % 3, (i + k) % 6, (i * k) % 4) for i in range(k))
    # The ranges' bounds.
    out["lower_bounds_3_vehicles"] = header("lo", rng, 3) + b"".join(vehicle("lo", rng, i, i, i) for i in range(3))
    out["upper_bounds_3_vehicles"] = header("hi", rng, 3, main_lanes=3) + b"".join(
        vehicle("hi", rng, i, 5 - i, 3 - i) for i in range(3))
    # Random grid values.
    for i in range(6):
        k = 1 + i
        out[f"random_{i}"] = header("random", rng, k, main_lanes=1 + i % 3, ego_v2v=i % 2) + b"".join(
            vehicle("random", rng, rng.randint(0, 2), rng.randint(0, 5), rng.randint(0, 3), rng.randint(0, 1))
            for _ in range(k))
    return out


def main():
    OUT.mkdir(exist_ok=True)
    for old in OUT.iterdir():
        old.unlink()
    for name, data in seeds().items():
        (OUT / name).write_bytes(data)


if __name__ == "__main__":
    main()
