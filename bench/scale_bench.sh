#!/usr/bin/env bash
# Memory and time of `mergeguard check` as the scene grows: a merge with N main-lane
# vehicles (IDM, spread over 4 lanes, 60 m apart in each) and a long horizon. Prints one line per size:
# vehicles, horizon, peak resident memory (MB), wall and CPU (user + system) time (s), the HTML
# report's size (KB) and the verdict. CPU time is the steadier figure on a shared machine.
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
    vehicles.append({"id": k + 1, "lane": lane, "x_m": -400.0 + 60.0 * (k // lanes) + 13.0 * lane,
                     "speed_mps": 22.0 + 0.5 * lane, "behaviour": {"type": "idm"}})
print(json.dumps({"format_version": 1, "name": f"scale_{n}_vehicles",
                  "description": f"scale benchmark: {n} main-lane vehicles, {horizon:g} s",
                  "road": {"main_lanes": lanes, "side_lane_end_x_m": 300.0},
                  "ego": {"x_m": 20.0, "speed_mps": 20.0}, "vehicles": vehicles,
                  "params": {"sim": {"horizon_s": horizon}}}, indent=1))
PY
}

printf '%-9s %-10s %-12s %-8s %-8s %-8s %s\n' vehicles horizon_s peak_rss_MB wall_s cpu_s html_KB verdict
for n in "${sizes[@]}"; do
  scenario "$n" "$horizon" > "$work/s$n.json"
  rm -rf "$work/r$n"
  status=0
  /usr/bin/time -f '%M %e %U %S' -o "$work/time$n" "$bin" check "$work/s$n.json" --report "$work/r$n" > "$work/out$n" || status=$?
  [ "$status" -le 1 ] || { echo "scale_bench: check of $n vehicles failed (exit $status)" >&2; cat "$work/out$n" >&2; exit 1; }
  read -r kb secs user sys < <(tail -n 1 "$work/time$n")
  html_kb=$(( $(stat -c %s "$work/r$n/report.html") / 1024 ))
  printf '%-9s %-10s %-12s %-8s %-8s %-8s %s\n' "$n" "$horizon" "$(( kb / 1024 ))" "$secs" \
    "$(awk -v u="$user" -v s="$sys" 'BEGIN { printf "%.2f", u + s }')" "$html_kb" \
    "$(sed -n 's/^verdict: *//p' "$work/out$n")"
done
