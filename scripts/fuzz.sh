#!/usr/bin/env bash
# Builds the libFuzzer targets (CMakePresets.json, preset "fuzz": clang, ASan+UBSan, core only) and runs
# each for KERF_FUZZ_SECONDS (default 300) on one core, niced, KERF_FUZZ_JOBS of them at once (default 1).
# docs/reliability.md has the numbers.
#
#   bash scripts/fuzz.sh                    # every target
#   bash scripts/fuzz.sh fuzz_project       # one target
#   KERF_FUZZ_SECONDS=1200 KERF_FUZZ_JOBS=2 bash scripts/fuzz.sh   # 20 minutes each, two at a time
#
# Seeds: fuzz/corpus/<target>/ (checked in, small), the CLI tests' projects and the demo block's output
# (made here by kerf-cli). New corpus entries go to build/fuzz/corpus/<target>/, crashes to
# build/fuzz/crashes/; keep a crasher as a regression test in tests/bad_inputs/test_parser_regressions.cpp.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${KERF_FUZZ_SECONDS:-300}"
all=(fuzz_project fuzz_sample_folder fuzz_mokume_images fuzz_contours fuzz_log_json fuzz_log_maps fuzz_cli_arguments)
[ $# -gt 0 ] && targets=("$@") || targets=("${all[@]}")

if ! command -v clang++ >/dev/null || ! ls /usr/lib/llvm-*/lib/clang/*/lib/linux/libclang_rt.fuzzer-x86_64.a >/dev/null 2>&1; then
  echo "fuzz.sh: libFuzzer needs clang and its runtime: apt-get install clang libclang-rt-14-dev" >&2
  exit 2
fi

launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake --preset fuzz "${launcher[@]}" >/dev/null
# kerf-cli makes the demo seeds; KERF_CLI=path/to/kerf-cli uses one already built instead.
cli="${KERF_CLI:-build/fuzz/app/kerf-cli}"
extra=()
[ -z "${KERF_CLI:-}" ] && extra=(kerf-cli)
nice -n 19 cmake --build build/fuzz -j 2 --target "${targets[@]}" "${extra[@]}"

corpus=build/fuzz/corpus
mkdir -p build/fuzz/crashes build/fuzz/logs
for t in "${all[@]}"; do mkdir -p "$corpus/$t"; done
cp tests/cli/*.kerf "$corpus/fuzz_project/"
if [ ! -f build/fuzz/demo/demo.kerf ]; then
  "$cli" -q demo --out build/fuzz/demo --size 24 --samples 1 >/dev/null
  "$cli" -q demo --out build/fuzz/demo-knot --size 24 --samples 1 --knot >/dev/null
fi
cp build/fuzz/demo/demo.kerf "$corpus/fuzz_project/demo.kerf"
cp build/fuzz/demo-knot/demo.kerf "$corpus/fuzz_project/demo-knot.kerf"

export ASAN_OPTIONS="abort_on_error=1:detect_leaks=1"
export UBSAN_OPTIONS="halt_on_error=1:abort_on_error=1:print_stacktrace=1"
run_target() {
  local t="$1" seeds=()
  [ -d "fuzz/corpus/$t" ] && seeds=("fuzz/corpus/$t")
  nice -n 19 "build/fuzz/fuzz/$t" "$corpus/$t" "${seeds[@]}" -max_total_time="$seconds" -max_len=4096 -len_control=0 -timeout=20 \
    -rss_limit_mb=2560 -print_final_stats=1 -artifact_prefix="build/fuzz/crashes/$t-" \
    >"build/fuzz/logs/$t.log" 2>&1 || echo "   $t stopped with a finding: see build/fuzz/logs/$t.log"
}
# KERF_FUZZ_JOBS targets run at once, one core each (default 1).
lanes="${KERF_FUZZ_JOBS:-1}"
for t in "${targets[@]}"; do
  echo "== $t: $seconds s"
  run_target "$t" &
  while [ "$(jobs -rp | wc -l)" -ge "$lanes" ]; do wait -n || true; done
done
wait
for t in "${targets[@]}"; do
  echo "== $t"
  grep -E "^#[0-9]+ +DONE|stat::number_of_executed_units|stat::peak_rss_mb" "build/fuzz/logs/$t.log" | sed 's/^/   /'
done
