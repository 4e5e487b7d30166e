#!/usr/bin/env bash
# Set-up command 1: install what Kerf needs, build it in Release and run the main job on the bundled
# demo block: the editor where there is a display, otherwise the headless pipeline (faces, a cut and
# volumes written to build/release/demo-output).
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/install-deps.sh
cmake -S . -B build/release -G Ninja -DCMAKE_BUILD_TYPE=Release -DKERF_BUILD_TESTS=OFF -DKERF_BUILD_BENCH=OFF >/dev/null
cmake --build build/release

cli=build/release/app/kerf-cli
demo=build/release/demo
[ -f "$demo/demo.kerf" ] || "$cli" demo --out "$demo"

if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ] && [ -z "${KERF_HEADLESS:-}" ]; then
  echo "Starting the Kerf editor on the demo block ($demo/demo.kerf)"
  exec build/release/app/editor/kerf "$demo/demo.kerf"
fi

echo "No display found: running the headless pipeline on the demo block instead."
out=build/release/demo-output
mkdir -p "$out"
"$cli" -q --stats render-faces "$demo/demo.kerf" --out "$out/faces" --px-per-mm 12.8 --unfolded
"$cli" -q --stats render-cut "$demo/demo.kerf" --plane 0,0,0,1,1,1 --px-per-mm 20 --out "$out/cut-diagonal.png"
"$cli" -q --stats export-volume "$demo/demo.kerf" --quantity growth --res 128 --out "$out/growth.nrrd"
"$cli" -q --stats export-volume "$demo/demo.kerf" --quantity color --res 128 --out "$out/color.nrrd"
cat <<MSG

Done. Outputs of the headless pipeline, in $(cd "$out" && pwd):
  faces/A.png .. F.png, faces/unfolded.png   the model's six faces, and unfolded as a cross
  cut-diagonal.png                           a diagonal cut through the block centre
  growth.nrrd, color.nrrd                    the growth field (years) and the colour, 128^3 volumes
The demo's input photos and true parameters are in $(cd "$demo" && pwd).
MSG
