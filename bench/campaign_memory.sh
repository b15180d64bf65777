#!/usr/bin/env bash
# Resident memory of a long fuzz campaign: runs `mergeguard fuzz --time S --jobs 1`
# at nice 10, samples VmRSS every 10 s and prints each sample and the least-squares slope
# (MB per hour) over the samples after the first minute (warm-up: allocator pools, corpus read).
#   bash bench/campaign_memory.sh [BINARY] [SECONDS]          defaults: build/mergeguard 1800
set -euo pipefail
bin=${1:-build/mergeguard}
seconds=${2:-1800}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
nice -n 10 "$bin" fuzz --time "$seconds" --jobs 1 --seed 20 --planner rcpp --corpus "$work/corpus" \
  --report "$work/report" > "$work/summary" 2> "$work/log" &
pid=$!
: > "$work/samples"
start=$(date +%s)
while kill -0 "$pid" 2>/dev/null; do
  rss_kb=$(awk '/^VmRSS/ {print $2}' "/proc/$pid/status" 2>/dev/null || true)
  [ -n "$rss_kb" ] && echo "$(( $(date +%s) - start )) $rss_kb" | tee -a "$work/samples"
  sleep 10
done
status=0
wait "$pid" || status=$?
echo "campaign exit $status: $(tail -n 1 "$work/summary")"
awk '$1 >= 60 { n++; sx += $1; sy += $2 / 1024; sxx += $1 * $1; sxy += $1 * $2 / 1024;
               if (min == "" || $2 < min) min = $2; if ($2 > max) max = $2 }
     END { if (n < 2) { print "too few samples"; exit }
           slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
           printf "samples after 60 s: %d, VmRSS %.1f..%.1f MB, slope %.3f MB/hour\n", n, min / 1024, max / 1024, slope * 3600 }' \
  "$work/samples"
