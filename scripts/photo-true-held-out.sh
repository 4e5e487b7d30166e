#!/usr/bin/env bash
# CN03 leave-one-face-out for the photo-true appearance (issue 17, docs/texture.md "Photo-true
# appearance"): for each face X in A..F, the growth field is fitted without X's photo, the project is
# switched to the photo-true appearance, its six faces are rendered, and face X is scored against its real
# photo with ../shared/eval/appearance_eval.py. Prints the per-face table, the means (contrast, orient,
# corr, style) and the wall time of each render-faces (the synthesis of six 256 x 256 faces).
#
#   bash scripts/photo-true-held-out.sh [--out DIR] [--shared DIR] [--seeds "1 2 3"] [FACES]
#
# FACES default ABCDEF. --seeds: the synthesis runs once per model.seed (default: 1, the fit's); the
# table shows each face's mean over the seeds, then the mean of each seed. One seed's scores of a face
# vary by about 0.1 in orient from seed to seed: compare changes over several seeds.
# The fits (DIR/hoX.kerf, about 10 s each) are kept in DIR and reused when present: delete them to refit.
# Everything else is redone on every run. Also writes DIR/side_by_side.png (photo | photo-true of the
# first seed, each face as held out, A..F top to bottom) to look at. Needs a built kerf-cli
# (build/test/app/kerf-cli, or KERF_CLI=path) and /usr/bin/python3 with numpy, scipy and OpenCV
# (KERF_PYTHON to use another). The wall times depend on the machine's load: the script prints uptime.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cli="${KERF_CLI:-$root/build/test/app/kerf-cli}"
out="$root/build/photo-true-held-out"
shared="$root/../shared"
seeds="1"
while [ $# -gt 0 ]; do
  case "$1" in
    --out) out="$2"; shift 2 ;;
    --shared) shared="$2"; shift 2 ;;
    --seeds) seeds="$2"; shift 2 ;;
    *) break ;;
  esac
done
faces="${1:-ABCDEF}"
python="${KERF_PYTHON:-/usr/bin/python3}"
sample="$shared/data/mokume/CN03"
evaluator="$shared/eval/appearance_eval.py"
[ -x "$cli" ] || { echo "photo-true-held-out: no kerf-cli at $cli (build first, or set KERF_CLI)" >&2; exit 2; }
[ -d "$sample" ] || { echo "photo-true-held-out: no CN03 sample at $sample (give --shared DIR)" >&2; exit 2; }
[ -f "$evaluator" ] || { echo "photo-true-held-out: no evaluator at $evaluator" >&2; exit 2; }
mkdir -p "$out"
echo "load before: $(uptime)"
for (( i = 0; i < ${#faces}; i++ )); do
  x="${faces:$i:1}"
  if [ ! -f "$out/ho$x.kerf" ]; then
    "$cli" -q fit "$sample" --hold-out-face "$x" --out "$out/ho$x.kerf" > /dev/null
  fi
  "$cli" -q texture "$out/ho$x.kerf" --out "$out/pt$x.kerf" --appearance photo > /dev/null
  for seed in $seeds; do
    run="pt${x}_s$seed"
    "$python" -c 'import json, sys
project = json.load(open(sys.argv[1]))
project["parameters"]["model.seed"] = int(sys.argv[3])
json.dump(project, open(sys.argv[2], "w"), indent=1)' "$out/pt$x.kerf" "$out/$run.kerf" "$seed"
    rm -rf "$out/${run}_faces"
    start=$(date +%s.%N)
    "$cli" -q render-faces "$out/$run.kerf" --out "$out/${run}_faces" > /dev/null
    end=$(date +%s.%N)
    echo "$end - $start" | bc > "$out/time_$run.txt"
    "$python" "$evaluator" "$sample" "$out/${run}_faces" --out "$out/eval_$run.json" > /dev/null
  done
done
echo "load after: $(uptime)"
"$python" - "$out" "$sample" "$faces" "$seeds" << 'PYTHON'
import json, os, sys
import cv2
import numpy as np

out, sample, faces, seeds = sys.argv[1:]
seeds = seeds.split()
keys = ("contrast", "orient", "corr", "style")
scores, seconds = {}, {}
for x in faces:
    for s in seeds:
        run = "pt%s_s%s" % (x, s)
        scores[x, s] = json.load(open(os.path.join(out, "eval_%s.json" % run)))["faces"][x]
        seconds[x, s] = float(open(os.path.join(out, "time_%s.txt" % run)).read())
print("seeds: " + " ".join(seeds))
print("| face | contrast | orient | corr | style | render-faces wall s |")
print("|---|---|---|---|---|---|")
rows = []
for x in faces:
    row = [np.mean([scores[x, s][k] for s in seeds]) for k in keys] + [np.mean([seconds[x, s] for s in seeds])]
    rows.append(row)
    print("| %s | %s | %.1f |" % (x, " | ".join("%.2f" % v for v in row[:4]), row[4]))
mean = np.mean(rows, 0)
print("| **mean** | %s | %.1f |" % (" | ".join("**%.2f**" % v for v in mean[:4]), mean[4]))
if len(seeds) > 1:
    for s in seeds:
        means = [np.mean([scores[x, s][k] for x in faces]) for k in keys]
        print("| mean, seed %s | %s | |" % (s, " | ".join("%.2f" % v for v in means)))
pictures = []
for x in faces:
    photo = cv2.imread(os.path.join(sample, x + "_col.png"))
    render = cv2.imread(os.path.join(out, "pt%s_s%s_faces" % (x, seeds[0]), x + ".png"))
    render = cv2.resize(render, photo.shape[1::-1], interpolation=cv2.INTER_AREA)
    pictures.append(np.hstack([photo, render]))
width = max(p.shape[1] for p in pictures)
pictures = [cv2.copyMakeBorder(p, 0, 4, 0, width - p.shape[1], cv2.BORDER_CONSTANT) for p in pictures]
cv2.imwrite(os.path.join(out, "side_by_side.png"), np.vstack(pictures))
PYTHON
