#!/usr/bin/env bash
# Wall-clock seconds of the shape_analysis tool on a fixed set of runs over CGAL's demo meshes
# and, when ../shared/data/lidar is there, a KITTI scan: reading (OFF, PLY, KITTI), writing three
# outputs as one set, the hierarchical partition sampler, segmentation of objects at locations
# (the grid walks), symmetry detection on an open mesh, registration. Each run is repeated and
# the best time kept. To compare two builds (before/after a change), run it on both tools in turn
# under the same load.
#
#   bench/cli_timings.sh TOOL [REPEATS=5] [DATA=build/data]   -> JSON on stdout
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
tool="$1"
repeats="${2:-5}"
data="${3:-$root/build/data}"
lidar="$root/../shared/data/lidar"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

best_of() { # best_of NAME ARGS... : prints one JSON member
  local name="$1" best="" t0 t1 s
  shift
  for ((i = 0; i < repeats; ++i)); do
    t0="$(date +%s.%N)"
    "$tool" "$@" -q >/dev/null 2>"$work/err" || { echo "\"$name\": null,"; cat "$work/err" >&2; return; }
    t1="$(date +%s.%N)"
    s="$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.6f", b - a }')"
    if [ -z "$best" ] || awk -v s="$s" -v b="$best" 'BEGIN { exit !(s < b) }'; then best="$s"; fi
  done
  printf '  "%s": %.4f,\n' "$name" "$best"
}

echo "{"
echo "  \"tool\": \"$tool\", \"repeats\": $repeats,"
best_of segment_armadillo_3_outputs segment "$data/armadillo.off" -k 8 -o "$work/a.ply" --seg "$work/a.seg" --report "$work/a.json"
best_of partition_hierarchical_cow_500_clusters partition "$data/cow.off" --method hierarchical --clusters 500 -n 8 --threads 1 --edge-values "$work/e.txt"
best_of symmetry_detect_head_open symmetry detect "$data/head.off" --threads 1 --report "$work/s.json"
best_of symmetry_detect_cow symmetry detect "$data/cow.off" --threads 1 --report "$work/s.json"
best_of register_elephant_onto_cow register "$data/elephant.off" "$data/cow.off" --threads 1 --report "$work/r.json"
best_of points_background_b9 points background "$data/b9_training.ply" -o "$work/b.ply"
if [ -f "$lidar/kitti_000003.bin" ]; then
  "$tool" points locate "$lidar/kitti_000003.bin" -o "$work/l.csv" -q >/dev/null
  best_of points_locate_kitti points locate "$lidar/kitti_000003.bin" -o "$work/l2.csv"
  best_of points_segment_kitti_mincut points segment "$lidar/kitti_000003.bin" --locations "$work/l.csv" --method mincut -o "$work/s.ply"
fi
echo "  \"end\": null"
echo "}"
