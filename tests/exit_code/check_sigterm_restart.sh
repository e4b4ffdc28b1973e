#!/bin/sh
# Usage: check_sigterm_restart.sh PG_SOLVE FULL STOPPED
# FULL.prm and STOPPED.prm are the same run with the output directories
# FULL and STOPPED. Runs FULL to the end; starts STOPPED, sends it SIGTERM
# after its first progress line and requires exit code 143, a checkpoint,
# "status": "interrupted" in summary.json and the message on standard
# error; continues STOPPED with --restart and requires the statistics.txt
# of FULL, the wall time column aside.
set -u
PG=$1
FULL=$2
STOPPED=$3
fail() {
  echo "FAILED: $*"
  exit 1
}
rm -rf "$FULL" "$STOPPED"
"$PG" "$FULL.prm" > "$FULL.log" 2>&1 || fail "$FULL.prm did not run"

# (the old log removed first: the loop must not read it before the shell
# of the background run has truncated it)
rm -f "$STOPPED.log" "$STOPPED.err"
"$PG" "$STOPPED.prm" > "$STOPPED.log" 2> "$STOPPED.err" &
pid=$!
i=0
while [ $i -lt 1200 ] && ! grep -q '^  t = .*, step [1-9]' "$STOPPED.log" 2> /dev/null; do
  sleep 0.05
  i=$((i + 1))
done
kill -TERM $pid
wait $pid
code=$?
[ $code -eq 143 ] || fail "exit code $code after SIGTERM, expected 143"
grep -q "Stopped by SIGTERM after time step [0-9]* (t = [0-9.]*)" "$STOPPED.err" ||
  fail "no 'Stopped by SIGTERM' message: $(cat "$STOPPED.err")"
[ -f "$STOPPED/checkpoint/rank-0.bin" ] || fail "no checkpoint"
grep -q '"status": "interrupted"' "$STOPPED/summary.json" ||
  fail "summary.json does not say interrupted"
echo "stopped: $(cat "$STOPPED.err" | tr -s '\n' ' ')"

"$PG" --restart "$STOPPED.prm" > "$STOPPED.restart.log" 2>&1 ||
  fail "the restart failed: $(tail -5 "$STOPPED.restart.log")"
grep -q '"status": "finished"' "$STOPPED/summary.json" ||
  fail "summary.json of the restart does not say finished"
# statistics.txt without its last column (wall time)
strip() {
  awk '/^#/ { print; next } { $NF = ""; print }' "$1"
}
strip "$FULL/statistics.txt" > "$FULL.statistics"
strip "$STOPPED/statistics.txt" > "$STOPPED.statistics"
cmp -s "$FULL.statistics" "$STOPPED.statistics" ||
  fail "statistics.txt differs: $(diff "$FULL.statistics" "$STOPPED.statistics" | head -5)"
echo "restarted: statistics.txt equal to the run without interruption"
