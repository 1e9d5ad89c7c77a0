#!/usr/bin/env bash
# Strata against CesiumJS on the peer benchmark's three views (docs/benchmarks.md, "Against CesiumJS"), in
# one run on this machine: the CesiumJS runner (a folder holding its package.json, run.mjs and index.html)
# in headless Chromium, then `strata bench` with a still camera on each view for pipelines/peer_imagery.yaml
# (the peer's scene: one image on the bare sphere) and pipelines/demo.yaml (image, geoid heights, relief).
# Writes OUT/peer-bench.md, the median frame times and their ratios. Not run by CI: it takes minutes, and
# needs Node, npm and Debian's chromium (the runner's README says how to install them).
#
# Usage: scripts/peer-bench.sh RUNNER_DIR [--out DIR] [--frames N] [--msaa N]
#   --out     where the runner's copy, its results and Strata's CSVs go (default out/peer-bench)
#   --frames  frames timed per view, both sides (default 50: the runner's sync frames)
#   --msaa    MSAA samples on both sides: CesiumJS's msaaSamples and Strata's output.image antialiasing
#             (0: none; default 4, both sides' own default)
set -euo pipefail
cd "$(dirname "$0")/.."
usage() { echo "usage: scripts/peer-bench.sh RUNNER_DIR [--out DIR] [--frames N] [--msaa N]" >&2; exit 2; }
[[ $# -ge 1 ]] || usage
runner=$(realpath "$1"); shift
out=out/peer-bench; frames=50; msaa=4
while [[ $# -gt 0 ]]; do
  case $1 in
    --out) out=$2; shift 2 ;;
    --frames) frames=$2; shift 2 ;;
    --msaa) msaa=$2; shift 2 ;;
    *) usage ;;
  esac
done
[[ -f $runner/run.mjs ]] || { echo "peer-bench: $runner holds no run.mjs: give the CesiumJS runner's folder" >&2; exit 2; }
mkdir -p "$out"; out=$(realpath "$out")

# CesiumJS: a scratch copy of the runner (its folder may be read-only), its pinned packages, one run.
rm -rf "$out/cesium"; mkdir -p "$out/cesium"
(cd "$runner" && tar --exclude=./node_modules --exclude=./out -cf - .) | tar -xf - -C "$out/cesium"
chmod -R u+w "$out/cesium"
(cd "$out/cesium" && npm ci --no-audit --no-fund >/dev/null)
(cd "$out/cesium" && node run.mjs --backend angle-gl-egl --vsync --runs 1 --frames "$frames" \
   --sync-frames "$frames" --msaa "$msaa" --tag peer)

# Strata: each view a still two-keyframe path, timed by `strata bench`.
scripts/build.sh >/dev/null
view_path() { # name altitude tilt
  printf 'strata-path: 1\nkeyframes:\n  - {time: 0, lon: 10, lat: 20, altitude: %s, tilt: %s, fov: 36}\n  - {time: 1, lon: 10, lat: 20, altitude: %s, tilt: %s, fov: 36}\n' \
    "$2" "$3" "$2" "$3" >"$out/path-$1.yaml"
}
view_path a 2.0e7 0; view_path b 2.0e6 0; view_path c 5000 60
# The median of a bench CSV's column, by name.
median_of() { # csv column
  awk -F, -v name="$2" 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == name) c = i; next } { print $c }' "$1" |
    sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'
}
antialiasing=$([[ $msaa -le 1 ]] && echo none || echo "${msaa}x")
for pipeline in peer_imagery demo; do
  for v in a b c; do
    build/bin/strata bench "pipelines/$pipeline.yaml" --set "nodes.frame.antialiasing=$antialiasing" \
      --path "$out/path-$v.yaml" --size 1280x720 \
      --frames "$frames" --average 1 --overwrite -o "$out/$pipeline-$v.csv" >"$out/$pipeline-$v.log" 2>&1
  done
done

# The table: CesiumJS's sync frame (render + readPixels) against Strata's frame (render + glFinish).
cesium_ms() { node -e "const r = require('$out/cesium/out/peer/results.json'); console.log(r.summary['$1'].sync.medianOfMedians.toFixed(1))"; }
{
  echo "| view | CesiumJS ms (MSAA $msaa) | Strata image ms (antialiasing $antialiasing) | triangles | ratio | Strata demo ms | ratio |"
  echo "| --- | --- | --- | --- | --- | --- | --- |"
  for v in a b c; do
    c=$(cesium_ms "$v"); i=$(median_of "$out/peer_imagery-$v.csv" frame_ms); d=$(median_of "$out/demo-$v.csv" frame_ms)
    t=$(median_of "$out/peer_imagery-$v.csv" triangles)
    awk -v v="$v" -v c="$c" -v i="$i" -v d="$d" -v t="$t" \
      'BEGIN { printf "| %s | %.1f | %.1f | %d | %.2f | %.1f | %.2f |\n", v, c, i, t, c / i, d, c / d }'
  done
  echo
  echo "$(grep -m1 'renderer:' "$out/cesium/out/peer/summary.md" || true)"
  echo "Strata: $(grep -m1 'strata: bench' "$out/peer_imagery-a.log" | sed 's/.* on //'); $frames frames a view; $(nproc) cores"
} >"$out/peer-bench.md"
cat "$out/peer-bench.md"
