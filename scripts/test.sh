#!/usr/bin/env bash
# Set-up command 2: install what Kerf needs, build everything and run every test (unit, golden-image,
# CLI end-to-end, and the GUI tests under xvfb-run).
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/install-deps.sh
cmake -S . -B build/test -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build/test
cd build/test
ctest --output-on-failure -j "$(nproc)" --timeout 600
