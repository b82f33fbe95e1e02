#!/usr/bin/env bash
# Fuzzes the readers and the option parsing of shape_analysis with libFuzzer (clang, ASan and
# UBSan), in build-fuzz/: each target for SECONDS (default 600), its corpus seeded from the
# bad-input catalogue's inputs, the test meshes and the catalogue's command lines. Prints the
# executions and findings per target; crash inputs go to build-fuzz/findings/<target>/.
# Usage: scripts/fuzz.sh [SECONDS] [TARGET...]   (targets: see test/fuzz/fuzz_inputs.cpp)
# SHAPE_ANALYSIS_FUZZ_DIR: the build folder instead of build-fuzz/.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
seconds="${1:-600}"
shift || true
targets=("$@")
if [ "${#targets[@]}" -eq 0 ]; then
  targets=(off ply_mesh obj stl ply xyz las kitti pieces_ply pieces_las pieces_kitti seg locations truth labels model osm command_line)
fi
"$root/scripts/install_dependencies.sh" clang libclang-rt-14-dev
out="${SHAPE_ANALYSIS_FUZZ_DIR:-$root/build-fuzz}" # (another folder: a second pass beside a running one)
cmake -S "$root" -B "$out" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" \
  -DSHAPE_ANALYSIS_SANITIZE=ON -DSHAPE_ANALYSIS_BUILD_FUZZERS=ON -DSHAPE_ANALYSIS_BUILD_TESTS=OFF \
  -DSHAPE_ANALYSIS_BUILD_EXAMPLES=OFF -DSHAPE_ANALYSIS_BUILD_BENCHMARKS=OFF -DSHAPE_ANALYSIS_WITH_MPI=OFF \
  -DCMAKE_CXX_FLAGS=-fsanitize=fuzzer-no-link >/dev/null
cmake --build "$out" --target shape_analysis_fuzz --parallel 2

# Seed corpora: the catalogue's inputs by type, the CGAL meshes of at most 200 kB, the command
# lines of the catalogue.
inputs="$out/seed_inputs"
c++ -std=c++17 -O1 "$root/test/cli/catalogue/make_inputs.cpp" -o "$out/catalogue_inputs"
"$out/catalogue_inputs" "$inputs"
seed() { # seed TARGET PATTERN...
  local t="$1"
  shift
  mkdir -p "$out/corpus/$t"
  for pattern in "$@"; do
    for f in $pattern; do
      if [ -f "$f" ] && [ "$(stat -c %s "$f")" -le 200000 ]; then cp "$f" "$out/corpus/$t/"; fi
    done
  done
}
data="$root/build/data"
seed off "$inputs/*.off" "$data/*.off"
seed ply_mesh "$inputs/*mesh*.ply" "$inputs/ellipsoid_colours.ply" "$inputs/few_colours.ply"
seed obj "$inputs/*.obj"
seed stl "$inputs/*.stl"
seed ply "$inputs/*cloud*.ply" "$inputs/one_point.ply" "$inputs/no_points.ply" "$inputs/nan_ascii.ply"
seed xyz "$inputs/*.xyz"
seed las "$inputs/*.las"
seed kitti "$inputs/*.bin"
seed pieces_ply "$inputs/*cloud*.ply" "$inputs/one_point.ply" "$inputs/no_points.ply" "$inputs/nan_ascii.ply"
seed pieces_las "$inputs/*.las"
seed pieces_kitti "$inputs/*.bin"
seed seg "$inputs/*.seg"
seed locations "$inputs/*location*.csv" "$inputs/locations.csv" "$inputs/no_header.csv" "$inputs/two_columns.csv"
seed truth "$inputs/*.json"
seed labels "$inputs/labels.csv" "$inputs/bad_labels.csv"
seed model "$inputs/*.json"
seed osm "$inputs/*.osm"
mkdir -p "$out/corpus/command_line"
n=0
grep -v '^#' "$root/test/cli/catalogue/cases.txt" | awk -F' [|] ' 'NF == 4 { print $4 }' | while read -r line; do
  n=$((n + 1))
  printf '%s' "$line" | sed -e "s|%IN%|$inputs|g" -e "s|%OUT%|/tmp/shape_analysis_fuzz_out|g" | tr -s ' ' '\n' \
    >"$out/corpus/command_line/case_$n"
done

printf '%-14s %12s %9s\n' target executions findings
status=0
for t in "${targets[@]}"; do
  mkdir -p "$out/findings/$t" "$out/logs"
  SHAPE_ANALYSIS_FUZZ="$t" ASAN_OPTIONS=detect_leaks=0 UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
    "$out/test/fuzz/shape_analysis_fuzz" "$out/corpus/$t" -max_total_time="$seconds" -timeout=20 \
    -rss_limit_mb=2560 -malloc_limit_mb=2048 -print_final_stats=1 -close_fd_mask=1 \
    -artifact_prefix="$out/findings/$t/" >"$out/logs/$t.log" 2>&1 || true
  executions="$(grep -ao 'stat::number_of_executed_units: *[0-9]*' "$out/logs/$t.log" | grep -o '[0-9]*$' || echo 0)"
  findings="$(find "$out/findings/$t" -type f | wc -l)"
  printf '%-14s %12s %9s\n' "$t" "${executions:-0}" "$findings"
  if [ "$findings" -gt 0 ]; then status=1; fi
done
exit "$status"
