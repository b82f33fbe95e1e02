#!/usr/bin/env bash
# The main job on packaged data: segments meshes from Debian's libcgal-demo into parts, computes
# the partition function of the camel and segments the elephant along its most consistent cuts,
# segments four animals consistently and the cow symmetrically, finds the cow's symmetry planes,
# symmetrizes it and exaggerates its asymmetries, and mirrors colours across the camel's plane;
# scans a procedural street with a simulated LIDAR and removes the background of it and of an
# airborne scan;
# writes coloured meshes (open them in MeshLab or CloudCompare), Princeton-benchmark label files,
# edge values and JSON reports to build/demo/. Installs missing Debian packages and builds the
# tool first.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

cmake --build "$root/build" --parallel "$jobs" --target shape_analysis

tool="$root/build/src/shape_analysis"
data="$root/build/data"
out="$root/build/demo"
mkdir -p "$out"

segment() { # mesh number_of_segments
  local name="$1" k="$2"
  "$tool" segment "$data/$name.off" --segments "$k" \
    --output "$out/${name}_segments.ply" --seg "$out/${name}_segments.seg" \
    --report "$out/${name}_segments.json" --verbose
}

segment camel 10
segment armadillo 12
segment bear 8
segment blobby_3cc 3

# The partition function (Randomized_cuts): how often random segmentations cut each edge,
# coloured from light grey to dark red, and a segmentation along the most consistent cuts.
"$tool" partition "$data/camel.off" --samples 400 --output "$out/camel_partition.ply" \
  --edge-values "$out/camel_partition.txt" --report "$out/camel_partition.json" --verbose
"$tool" partition-segment "$data/elephant.off" --segments 6 \
  --output "$out/elephant_partition_segments.ply" --seg "$out/elephant_partition_segments.seg" \
  --report "$out/elephant_partition_segments.json" --verbose

# Consistent segmentation (Consistent_segmentation): four-legged animals segmented together, the
# same colour for the same part in every mesh, and the cow segmented symmetrically.
"$tool" coseg "$data/cow.off" "$data/bull.off" "$data/elephant.off" "$data/camel.off" --segments 7 \
  --output-dir "$out/coseg" --report "$out/coseg.json" --verbose
"$tool" coseg "$data/cow.off" --segments 7 --symmetry-plane 0,0,1,0 \
  --output-dir "$out/coseg_symmetric" --report "$out/coseg_symmetric.json" --verbose

# Symmetry (Surface_mesh_symmetrization): the cow's reflective planes (faces coloured by their
# support), the cow made symmetric with its symmetric map, its asymmetries tripled, and the
# colours of the camel's partition function copied from one side of its plane to the other.
"$tool" symmetry detect "$data/cow.off" --report "$out/cow_symmetry.json" \
  --output "$out/cow_symmetry_support.ply" --verbose
"$tool" symmetry symmetrize "$data/cow.off" --output "$out/cow_symmetric.off" \
  --map "$out/cow_symmetric_map.txt" --report "$out/cow_symmetric.json" --verbose
"$tool" symmetry enhance "$data/cow.off" --symmetric "$out/cow_symmetric.off" --amount -2 \
  --output "$out/cow_asymmetry_tripled.off" --verbose
"$tool" symmetry transfer "$data/camel.off" --colors "$out/camel_partition.ply" \
  --output "$out/camel_partition_mirrored.ply" --report "$out/camel_partition_mirrored.json" --verbose

# Point clouds (Point_set_object_recognition): a street of 400 m scanned by a simulated mobile
# LIDAR (colours by class, the objects' ground truth in JSON), its background removed (ground,
# isolated points, buildings), its objects located (normalized cut, locations.csv), segmented
# (min-cut, street_segmented.ply) and checked against the truth (tables 4.1 and 4.2), and the background of
# CGAL's airborne scan b9_training.ply.
"$tool" points generate --seed 1 --points 1000000 --length 400 --output "$out/street_scan.ply" \
  --truth "$out/street_objects.json" --report "$out/street_scan.json" --verbose
"$tool" points background "$out/street_scan.ply" --output "$out/street_foreground.ply" \
  --report "$out/street_foreground.json" --verbose
"$tool" points locate "$out/street_scan.ply" --method nc --truth "$out/street_objects.json" \
  --output "$out/street_locations.csv" --report "$out/street_locations_report.json" --verbose
"$tool" points segment "$out/street_scan.ply" --locations "$out/street_locations.csv" --method mincut-auto \
  --output "$out/street_segmented.ply" --report "$out/street_segments.json" --verbose
"$tool" points evaluate --truth "$out/street_objects.json" --locations "$out/street_locations.csv" \
  --objects "$out/street_segmented.ply" --report "$out/street_evaluation.json"
# The same chain in one command, tile by tile (tiles of 100 m with a margin of 10 m), evaluated.
"$tool" points recognize "$out/street_scan.ply" --tile-size 100 --output "$out/street_recognized.ply" \
  --locations "$out/street_recognized.csv" --report "$out/street_recognized.json" --verbose
"$tool" points evaluate --truth "$out/street_objects.json" --locations "$out/street_recognized.csv" \
  --objects "$out/street_recognized.ply" --report "$out/street_recognized_evaluation.json"
# Recognition of classes: a random forest trained on another street (seed 2, its truth as labels)
# names the objects of the first (objects coloured by class, locations.csv with label and
# confidence), scored per class (the thesis' table 4.5).
"$tool" points generate --seed 2 --points 1000000 --length 400 --output "$out/street2_scan.ply" \
  --truth "$out/street2_objects.json" --verbose
"$tool" points train "$out/street2_scan.ply" --labels "$out/street2_objects.json" --min-points 20 \
  --output "$out/street_model.json" --report "$out/street_model_report.json" --verbose
"$tool" points recognize "$out/street_scan.ply" --model "$out/street_model.json" --tile-size 100 \
  --output "$out/street_classes.ply" --locations "$out/street_classes.csv" --verbose
"$tool" points evaluate --labels "$out/street_objects.json" --locations "$out/street_classes.csv" --min-points 20 \
  --report "$out/street_classes_evaluation.json"
"$tool" points background "$data/b9_training.ply" --max-extent 6 --spacing 1 --isolation-radius 1 \
  --output "$out/b9_foreground.ply" --report "$out/b9_foreground.json" --verbose

echo
echo "Coloured segmentations (per-face colours) and partition functions (per-vertex colours) in $out:"
ls -1 "$out"/*.ply "$out"/coseg/*.ply "$out"/coseg_symmetric/*.ply
echo "Symmetrized and enhanced meshes: $out/cow_symmetric.off, $out/cow_asymmetry_tripled.off"
echo "Point clouds: $out/street_scan.ply (objects: $out/street_objects.json), $out/street_foreground.ply, $out/street_segmented.ply, $out/street_recognized.ply (in tiles), $out/street_classes.ply (coloured by class), $out/b9_foreground.ply"
