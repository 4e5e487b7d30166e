#!/usr/bin/env bash
# The scheduled fuzz run (issue 21: "run each fuzz target for at least an hour in a documented scheduled
# run, not in CI"): every target of scripts/fuzz.sh for KERF_FUZZ_SECONDS (default 3600) each, two at a
# time, keeping the corpora in build/fuzz/corpus/ from run to run, and a dated summary in
# build/fuzz/runs/. Exit code 1 when any target stopped with a finding (its input is in
# build/fuzz/crashes/; keep it as a test in tests/bad_inputs/ and add it to docs/reliability.md).
#
# Not part of CI (.ci/run): seven hours of fuzzing on two cores take about 3.5 hours. Schedule it on an
# idle machine, e.g. weekly from cron:
#
#   0 1 * * 6  cd /path/to/kerf && git pull -q && bash scripts/fuzz-scheduled.sh >/dev/null 2>&1
#
# or run it by hand: `bash scripts/fuzz-scheduled.sh`, `KERF_FUZZ_SECONDS=600 bash scripts/fuzz-scheduled.sh
# fuzz_cli_arguments` (extra arguments pick targets, as for fuzz.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
export KERF_FUZZ_SECONDS="${KERF_FUZZ_SECONDS:-3600}"
export KERF_FUZZ_JOBS="${KERF_FUZZ_JOBS:-2}"
mkdir -p build/fuzz/runs build/fuzz/crashes
summary="build/fuzz/runs/$(date -u +%Y-%m-%dT%H%M%SZ).txt"
crashes_before=$(find build/fuzz/crashes -type f | wc -l)
{
  echo "kerf scheduled fuzz run, commit $(git rev-parse --short HEAD 2>/dev/null || echo unknown)"
  echo "$KERF_FUZZ_SECONDS s per target, $KERF_FUZZ_JOBS at a time, on $(nproc) cores"
  bash scripts/fuzz.sh "$@"
} 2>&1 | tee "$summary"
crashes_after=$(find build/fuzz/crashes -type f | wc -l)
if [ "$crashes_after" -gt "$crashes_before" ]; then
  echo "fuzz-scheduled: $((crashes_after - crashes_before)) new finding(s) in build/fuzz/crashes/" | tee -a "$summary"
  exit 1
fi
echo "fuzz-scheduled: no findings; summary in $summary"
