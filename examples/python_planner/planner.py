#!/usr/bin/env python3
"""A deliberately naive gap-acceptance merge planner for mergeguard's exec protocol.

Standard library only. It keeps its lane at its initial speed and starts merging into the main
lane once no main-lane vehicle is within a fixed distance of it (no speeds, no RSS reasoning), so
that `mergeguard fuzz` finds its flaws. Protocol: docs/planner_protocol.md.

    mergeguard fuzz --planner 'exec:python3 examples/python_planner/planner.py' --time 60
"""
import json
import math
import sys

GAP_LOOKS_BIG_M = 25.0   # naive on purpose: ignores relative speed and vehicle lengths
MERGE_LENGTH_M = 40.0    # the lane change is a smooth step over this distance
PATH_AHEAD_M = 80.0
PATH_STEP_M = 5.0


class NaivePlanner:
    def __init__(self):
        self.lane_width_m = 3.5
        self.speed_mps = 0.0
        self.merge_start_x_m = None
        self.merge_from_y_m = 0.0

    def reset(self, msg):
        self.lane_width_m = msg["road"].get("lane_width_m", 3.5)
        self.speed_mps = msg["ego"].get("speed_mps", 0.0)
        self.merge_start_x_m = None

    def gap_looks_big(self, ego, others):
        for other in others:
            in_main_lane = abs(other["y_m"]) < 0.5 * self.lane_width_m
            if in_main_lane and abs(other["x_m"] - ego["x_m"]) < GAP_LOOKS_BIG_M:
                return False
        return True

    def lateral_m(self, x_m, ego_y_m):
        if self.merge_start_x_m is None:
            return ego_y_m
        u = min(max((x_m - self.merge_start_x_m) / MERGE_LENGTH_M, 0.0), 1.0)
        smooth = 0.5 - 0.5 * math.cos(math.pi * u)
        return self.merge_from_y_m * (1.0 - smooth)

    def command(self, msg):
        ego = msg["ego"]
        in_side_lane = ego["y_m"] < -0.5 * self.lane_width_m
        if in_side_lane and self.merge_start_x_m is None and self.gap_looks_big(ego, msg["others"]):
            self.merge_start_x_m, self.merge_from_y_m = ego["x_m"], ego["y_m"]
        steps = int(PATH_AHEAD_M / PATH_STEP_M)
        xs = [ego["x_m"] + k * PATH_STEP_M for k in range(steps + 1)]
        path = [[x, self.lateral_m(x, ego["y_m"])] for x in xs]
        return {"type": "command", "path": path, "target_speed_mps": self.speed_mps,
                "accel_limit_mps2": 2.0,
                "annotation": {"merging": self.merge_start_x_m is not None}}


def main():
    planner = NaivePlanner()
    for line in sys.stdin:
        msg = json.loads(line)
        kind = msg.get("type")
        if kind == "hello":
            reply = {"type": "hello", "name": "python-naive-gap", "version": "1"}
        elif kind == "reset":
            planner.reset(msg)
            reply = {"type": "ready"}
        elif kind == "observe":
            reply = planner.command(msg)
        elif kind == "bye":
            return
        else:
            print("unknown message type: %r" % kind, file=sys.stderr)
            continue
        sys.stdout.write(json.dumps(reply) + "\n")
        sys.stdout.flush()


if __name__ == "__main__":
    main()
