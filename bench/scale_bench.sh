#!/usr/bin/env bash
# Memory and time of `mergeguard check` as the scene grows (issue 20): a merge with N main-lane
# vehicles (IDM, spread over 4 lanes, 45 m apart) and a long horizon. Prints one line per size:
# vehicles, horizon, peak resident memory (MB), wall time (s) and the HTML report's size (KB).
#   bash bench/scale_bench.sh [BINARY] [HORIZON_S] [N...]      defaults: build/mergeguard 600 8 64
set -euo pipefail
bin=${1:-build/mergeguard}
horizon=${2:-600}
shift $(( $# > 2 ? 2 : $# )) || true
sizes=("$@")
((${#sizes[@]})) || sizes=(8 64)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

scenario() {  # scenario N HORIZON > file
  python3 - "$1" "$2" <<'PY'
import json, sys
n, horizon = int(sys.argv[1]), float(sys.argv[2])
lanes = 4
vehicles = []
for k in range(n):
    lane = k % lanes
    vehicles.append({"id": k + 1, "lane": lane, "x_m": -200.0 + 45.0 * (k // lanes) + 11.0 * lane,
                     "speed_mps": 22.0 + 0.5 * lane, "behaviour": {"type": "idm"}})
print(json.dumps({"format_version": 1, "name": f"scale_{n}_vehicles",
                  "description": f"issue-20 scale benchmark: {n} main-lane vehicles, {horizon:g} s",
                  "road": {"main_lanes": lanes, "side_lane_end_x_m": 300.0},
                  "ego": {"x_m": 20.0, "speed_mps": 20.0}, "vehicles": vehicles,
                  "params": {"sim": {"horizon_s": horizon}}}, indent=1))
PY
}

printf '%-9s %-10s %-13s %-10s %-10s %s\n' vehicles horizon_s peak_rss_MB time_s html_KB verdict
for n in "${sizes[@]}"; do
  scenario "$n" "$horizon" > "$work/s$n.json"
  rm -rf "$work/r$n"
  status=0
  /usr/bin/time -f '%M %e' -o "$work/time$n" "$bin" check "$work/s$n.json" --report "$work/r$n" > "$work/out$n" || status=$?
  [ "$status" -le 1 ] || { echo "scale_bench: check of $n vehicles failed (exit $status)" >&2; cat "$work/out$n" >&2; exit 1; }
  read -r kb secs < <(tail -n 1 "$work/time$n")
  html_kb=$(( $(stat -c %s "$work/r$n/report.html") / 1024 ))
  printf '%-9s %-10s %-13s %-10s %-10s %s\n' "$n" "$horizon" "$(( kb / 1024 ))" "$secs" "$html_kb" \
    "$(sed -n 's/^verdict: *//p' "$work/out$n")"
done
