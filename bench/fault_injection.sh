#!/usr/bin/env bash
# Fault injection: prints its figures; not part of CTest (it takes a few minutes).
#   bash bench/fault_injection.sh [BINARY] [KILLS]        defaults: build/mergeguard 100
# 1. SIGKILL at KILLS random moments of campaigns writing into one corpus (2 jobs, small shrink
#    budget, so that cases are written often); then every case must load and replay, and no
#    temporary file may remain.
# 2. SIGTERM at random moments: the time from the signal to the exit (runs in flight finish).
# 3. Writes that fail: a file-size limit (prlimit --fsize), a full file system (a small tmpfs,
#    when mounting is allowed) and a read-only directory for a non-root user: exit 2, one line,
#    no partial case or report, no temporary file.
set -uo pipefail
bin=$(realpath "${1:-build/mergeguard}")
kills=${2:-100}
src=$(cd "$(dirname "$0")/.." && pwd)
scenario="$src/corpus/scenarios/bench_std4.json"
work=$(mktemp -d)
chmod 755 "$work"
trap 'umount "$work/full" 2>/dev/null; rm -rf "$work"' EXIT
fail=0
check() {  # check NAME CONDITION-TEXT STATUS
  if [ "$3" -eq 0 ]; then echo "  ok    $1: $2"; else echo "  FAIL  $1: $2"; fail=1; fi
}
temporaries() { find "$1" -name '*.tmp.*' 2>/dev/null | wc -l; }
one_line() { [ "$(wc -l < "$1")" -eq 1 ]; }

echo "1. SIGKILL at $kills random moments (delays drawn from seed 20)"
corpus="$work/corpus"
mkdir -p "$corpus"
delays=$(awk -v n="$kills" 'BEGIN { srand(20); for (i = 0; i < n; i++) printf "%.3f\n", 0.05 + 2.95 * rand() }')
leftover=0 refused=0 i=0
for d in $delays; do
  i=$((i + 1))
  "$bin" fuzz --planner tripfield --time 600 --jobs 2 --seed "$i" --shrink-attempts 20 --corpus "$corpus" \
    > /dev/null 2> "$work/err" &
  pid=$!
  sleep "$d"
  kill -KILL "$pid" 2>/dev/null
  wait "$pid" 2>/dev/null
  status=$?
  [ "$status" -eq 2 ] && refused=$((refused + 1)) && head -n 1 "$work/err"  # a campaign refused the corpus
  leftover=$((leftover + $(temporaries "$corpus")))
done
cases=$(find "$corpus" -name '*.json' | wc -l)
"$bin" replay "$corpus" > "$work/replay" 2>&1
replay_status=$?
echo "  $kills kills, $cases cases in the corpus, $(tail -n 1 "$work/replay")"
check "every case loads and replays" "replay exit $replay_status" "$replay_status"
check "no campaign refused the corpus" "$refused refusals" "$refused"
check "no temporary file after any kill" "$leftover temporary files seen" "$leftover"

echo "2. SIGTERM at 10 random moments: signal to exit"
latencies=""
for d in $(awk 'BEGIN { srand(21); for (i = 0; i < 10; i++) printf "%.3f\n", 0.3 + 4.7 * rand() }'); do
  "$bin" fuzz --planner rcpp --time 600 --jobs 2 --corpus "$work/term" --report "$work/term-report" --json \
    > "$work/term.json" 2> /dev/null &
  pid=$!
  sleep "$d"
  t0=$(date +%s.%N)
  kill -TERM "$pid"
  wait "$pid"
  status=$?
  t1=$(date +%s.%N)
  latencies="$latencies $(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.2f", b - a }')"
  [ "$status" -eq 3 ] && jq -e '.interrupted and .signal == "SIGTERM"' "$work/term.json" > /dev/null \
    && [ -f "$work/term-report/report.json" ] || { echo "  FAIL  SIGTERM: exit $status"; fail=1; }
done
max=$(echo "$latencies" | tr ' ' '\n' | sort -g | tail -n 1)
echo "  signal-to-exit seconds:$latencies (max $max)"
check "stopped within 10 s, exit 3, summary and report written" "max $max s" "$(awk -v m="$max" 'BEGIN { print (m < 10) ? 0 : 1 }')"

echo "3. Writes that fail"
refused_cleanly() {  # refused_cleanly NAME DIR EXPECTED-TEXT STATUS ERRFILE
  local name=$1 dir=$2 text=$3 status=$4 err=$5 partial
  partial=$(find "$dir" -name 'report.*' -o -name '*.tmp.*' 2>/dev/null | wc -l)
  check "$name" "exit $status, '$(head -c 150 "$err")'" "$(( status != 2 || partial != 0 ))"
  one_line "$err" && grep -q "$text" "$err" || { echo "  FAIL  $name: expected one line with '$text'"; fail=1; }
}
mkdir -p "$work/fsize"
prlimit --fsize=4096 "$bin" check "$scenario" --report "$work/fsize" > /dev/null 2> "$work/err"
refused_cleanly "check --report past a 4 KB file-size limit" "$work/fsize" "File too large" $? "$work/err"
mkdir -p "$work/fsize-corpus"
prlimit --fsize=1024 "$bin" fuzz --planner tripfield --time 60 --shrink-attempts 5 --corpus "$work/fsize-corpus" \
  > /dev/null 2> "$work/err"
status=$?
bad=0
for f in "$work"/fsize-corpus/*.json; do [ -e "$f" ] && { "$bin" replay "$f" > /dev/null 2>&1 || bad=$((bad + 1)); }; done
check "fuzz --corpus past a 1 KB file-size limit" "exit $status, '$(tail -n 1 "$work/err" | head -c 150)', $bad broken cases, $(temporaries "$work/fsize-corpus") temporaries" \
  "$(( status != 2 || bad != 0 || $(temporaries "$work/fsize-corpus") != 0 ))"
mkdir -p "$work/full"
if mount -t tmpfs -o size=64k tmpfs "$work/full" 2> /dev/null; then
  "$bin" check "$scenario" --report "$work/full/report" > /dev/null 2> "$work/err"
  refused_cleanly "check --report on a full 64 KB file system" "$work/full" "No space left" $? "$work/err"
  umount "$work/full"
else
  echo "  skip  full file system: cannot mount a tmpfs here"
fi
if [ "$(id -u)" -eq 0 ] && command -v setpriv > /dev/null; then
  mkdir -p "$work/ro"
  chown 65534:65534 "$work/ro"
  chmod 555 "$work/ro"
  setpriv --reuid=65534 --regid=65534 --clear-groups "$bin" check "$scenario" --report "$work/ro" > /dev/null 2> "$work/err"
  refused_cleanly "check --report into a read-only directory (uid 65534)" "$work/ro" "not writable (Permission denied)" $? "$work/err"
  setpriv --reuid=65534 --regid=65534 --clear-groups "$bin" fuzz --runs 5 --corpus "$work/ro" > /dev/null 2> "$work/err"
  refused_cleanly "fuzz --corpus into a read-only directory (uid 65534)" "$work/ro" "not writable (Permission denied)" $? "$work/err"
elif [ "$(id -u)" -ne 0 ]; then
  mkdir -p "$work/ro" && chmod 555 "$work/ro"
  "$bin" check "$scenario" --report "$work/ro" > /dev/null 2> "$work/err"
  refused_cleanly "check --report into a read-only directory" "$work/ro" "not writable (Permission denied)" $? "$work/err"
else
  echo "  skip  read-only directory: no setpriv to drop root"
fi
[ "$fail" -eq 0 ] && echo "fault injection: all checks passed" || echo "fault injection: FAILED"
exit "$fail"
