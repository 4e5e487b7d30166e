#!/usr/bin/env bash
# Synthetic species round trips for the texture inference (issue 16, docs/texture.md): for each species
# preset, the demo block's field is given that species' wood (the truth), its six faces are rendered at
# Mokume's 6.4 px/mm as the "photos", and `kerf-cli texture` infers the detail back from a start whose
# searched detail parameters are the schema's defaults, with another random seed (so only the statistics,
# not the pixels, can agree). Prints, per species, each searched parameter's truth, start and result, and,
# where ../shared/eval/appearance_eval.py and its Python modules are at hand, the yardstick on the six
# faces. Minutes per species on 2 cores.
#
#   bash scripts/species-round-trips.sh [--out DIR] [SPECIES ...]    # default: six kinds of wood
#
# Needs a built kerf-cli (build/test/app/kerf-cli, or KERF_CLI=path). KERF_TEXTURE_ARGS="--sweeps 8 ..." passes
# options to `kerf-cli texture` (e.g. to compare searches).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cli="${KERF_CLI:-$root/build/test/app/kerf-cli}"
out="$root/build/species-round-trips"
if [ "${1:-}" = "--out" ]; then out="$2"; shift 2; fi
species=("$@")
[ ${#species[@]} -gt 0 ] || species=(kuri red_oak maple beech sugi hinoki)
[ -x "$cli" ] || { echo "species-round-trips: no kerf-cli at $cli (build first, or set KERF_CLI)" >&2; exit 2; }
evaluator="$root/../shared/eval/appearance_eval.py"
python="${KERF_PYTHON:-python3}"  # the yardstick needs numpy and OpenCV's Python module
can_evaluate=0
if [ -f "$evaluator" ] && "$python" -c "import numpy, cv2" 2>/dev/null; then can_evaluate=1; fi

mkdir -p "$out"
"$cli" -q demo --out "$out/demo" --size 256 > /dev/null
"$cli" params > "$out/schema.json"
for id in "${species[@]}"; do
  preset="$root/resources/presets/$id.json"
  [ -f "$preset" ] || { echo "species-round-trips: no preset $preset" >&2; exit 2; }
  dir="$out/$id"
  rm -rf "$dir"
  mkdir -p "$dir"
  # The truth: the demo's block and field with the species' parameters; the start: the same with every
  # searched detail parameter at its schema default and another seed.
  python3 - "$out/demo/demo.kerf" "$preset" "$out/schema.json" "$dir" <<'EOF'
import json, sys
project, preset, schema, folder = sys.argv[1:]
truth = json.load(open(project))
truth["parameters"].update(json.load(open(preset))["parameters"])
json.dump(truth, open(folder + "/truth.kerf", "w"), indent=1)
start = json.loads(json.dumps(truth))
for spec in json.load(open(schema)):
    if "texture_search" in spec:
        start["parameters"][spec["id"]] = spec["default"]
start["parameters"]["model.seed"] = truth["parameters"].get("model.seed", 1) + 1000
json.dump(start, open(folder + "/start.kerf", "w"), indent=1)
EOF
  "$cli" -q render-faces "$dir/truth.kerf" --out "$dir/photos" --px-per-mm 6.4 --samples 2 > /dev/null
  for f in A B C D E F; do cp "$dir/photos/$f.png" "$dir/photos/${f}_col.png"; done
  # shellcheck disable=SC2086  # KERF_TEXTURE_ARGS: extra options of `kerf-cli texture`, word by word
  "$cli" --stats texture "$dir/start.kerf" --photos "$dir/photos" --out "$dir/found.kerf" ${KERF_TEXTURE_ARGS:-} \
    > "$dir/texture.log" 2>&1
  "$cli" -q render-faces "$dir/start.kerf" --out "$dir/start-faces" --px-per-mm 6.4 --samples 2 > /dev/null
  "$cli" -q render-faces "$dir/found.kerf" --out "$dir/found-faces" --px-per-mm 6.4 --samples 2 > /dev/null
  echo "== $id ($(grep -o 'time: .*' "$dir/texture.log"))"
  python3 - "$dir" "$out/schema.json" <<'EOF'
import json, sys
folder, schema = sys.argv[1:]
truth, start, found = (json.load(open(f"{folder}/{n}.kerf"))["parameters"] for n in ("truth", "start", "found"))
print(f"  {'parameter':26s} {'truth':>9s} {'start':>9s} {'found':>9s}")
for spec in json.load(open(schema)):
    if "texture_search" in spec:
        i = spec["id"]
        print(f"  {i:26s} {truth[i]:9.4f} {start[i]:9.4f} {found[i]:9.4f}")
EOF
  if [ "$can_evaluate" = 1 ]; then
    for faces in start-faces found-faces; do
      echo "  $faces: $("$python" "$evaluator" "$dir/photos" "$dir/$faces" --out "$dir/$faces.json" | tail -n 1)"
    done
  fi
done
