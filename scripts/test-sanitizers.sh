#!/usr/bin/env bash
# Builds Kerf with AddressSanitizer + UndefinedBehaviorSanitizer (CMakePresets.json, preset "asan") and runs
# the test suite under them; any report fails the test that triggered it (docs/reliability.md).
#
#   bash scripts/test-sanitizers.sh            # everything: core, CLI and GUI tests
#   bash scripts/test-sanitizers.sh -R '^cli'  # extra arguments go to ctest
#
# KERF_SAN_TARGETS="kerf-cli test_core" builds only those targets (then run a matching -R pattern).
# The build is niced: it is meant to run beside other work on a shared machine.
set -euo pipefail
cd "$(dirname "$0")/.."
root="$PWD"

launcher=()
if command -v ccache >/dev/null; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
jobs="${KERF_SAN_JOBS:-$(nproc)}"
cmake --preset asan "${launcher[@]}" >/dev/null
# shellcheck disable=SC2086  # the target list is meant to split
nice -n 19 cmake --build build/asan -j "$jobs" ${KERF_SAN_TARGETS:+--target $KERF_SAN_TARGETS}

# halt_on_error/abort_on_error: the first report ends the process with SIGABRT, which ctest and the CLI
# cases' run_case.cmake count as a crash, even in cases that expect kerf-cli to fail.
# No strict_string_checks: it flags libxkbcommon-x11's legal strndup of an unterminated buffer (Qt's xcb
# platform, kerf-cli render-board --gpu) as a heap overflow.
export ASAN_OPTIONS="halt_on_error=1:abort_on_error=1:detect_leaks=1:check_initialization_order=1:detect_stack_use_after_return=1:verify_asan_link_order=0"
export UBSAN_OPTIONS="halt_on_error=1:abort_on_error=1:print_stacktrace=1"
export LSAN_OPTIONS="suppressions=$root/scripts/lsan.supp:print_suppressions=0"
# Mesa's software driver leaks 2 x 56 bytes per OpenGL context and is unloaded (dlclose) before
# LeakSanitizer runs, so the leak can be neither attributed nor suppressed. Preloaded, the driver stays
# mapped: its globals still point at those blocks, which are then reachable, not leaked, and every GL
# test keeps its leak check (verify_asan_link_order=0 lets a library come before the ASan runtime).
driver=$(ls /usr/lib/*/dri/swrast_dri.so 2>/dev/null | head -n 1 || true)
[ -n "$driver" ] && export LD_PRELOAD="$driver${LD_PRELOAD:+ $LD_PRELOAD}"
cd build/asan
# As scripts/test.sh: everything but the latency measurements in parallel, then those (label `timing`)
# alone, so that no test's verdict depends on what runs beside it. Both passes run; either failing fails.
status=0
# The scripted walkthrough (label `walkthrough`, a whole CN03 reconstruction) runs in scripts/test.sh only.
# The repeated whole fits named in tests/sanitizer_heavy.txt run in scripts/test.sh only (see there why).
heavy=$(sed -e 's/#.*//' -e 's/[[:space:]]//g' -e '/^$/d' -e 's/\./\\./g' "$root/tests/sanitizer_heavy.txt" | paste -sd '|')
nice -n 19 ctest --output-on-failure -j "$jobs" --timeout 1800 -LE 'timing|walkthrough' -E "^($heavy)\$" "$@" \
  || status=1
nice -n 19 ctest --output-on-failure --timeout 1800 -L timing --no-tests=ignore "$@" || status=1
exit "$status"
