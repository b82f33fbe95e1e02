#!/usr/bin/env bash
# `points recognize` on generated streets of several sizes, the whole command timed (reading and
# writing included) and the peak resident memory of each process (GNU time's %M): the scan held
# in memory (one process), out of core (--work-dir, one process), and out of core on the ranks of
# `mpirun -np 2` (the tiles shared between the ranks; the peak of each rank), each with one thread
# per process unless THREADS says otherwise; whether the outputs are the same bytes; the work
# folder's size. A street of 400 m per million points, seed 8, tiles of 100 m.
#
#   bench/recognize_ranks.sh TOOL [SIZES=3000000] [THREADS=1] [REPEATS=3] [WORK=a temporary folder]  -> JSON on stdout
#
# SIZES: comma-separated numbers of points. Each size's street is generated once (not timed). Each
# run is repeated REPEATS times (a new work folder each time): the best time, and the peak memory
# and all times of every repeat.
# Needs GNU time (/usr/bin/time) and, for the ranks, mpirun (skipped without it).
set -euo pipefail
tool="$1"
sizes="${2:-3000000}"
threads="${3:-1}"
repeats="${4:-3}"
work="${5:-$(mktemp -d)}"
mkdir -p "$work"
[ -n "${5:-}" ] || trap 'rm -rf "$work"' EXIT
mpirun="$(command -v mpirun || true)"

# run NAME COMMAND...: the command's best seconds over the repeats, every repeat's seconds, the
# peak memory (of the largest process) and each process's, as a JSON member. The work folders
# w1 and w2 are emptied before each repeat.
run() {
  local name="$1" t0 t1 seconds="" best="" peaks=""
  shift
  for ((r = 0; r < repeats; ++r)); do
    rm -rf "$work"/peak.* "$work/w1" "$work/w2"
    t0="$(date +%s.%N)"
    "$@" >/dev/null 2>"$work/err" || { cat "$work/err" >&2; echo "    \"$name\": null,"; return; }
    t1="$(date +%s.%N)"
    local s
    s="$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.3f", b - a }')"
    seconds="${seconds:+$seconds, }$s"
    if [ -z "$best" ] || awk -v s="$s" -v b="$best" 'BEGIN { exit !(s < b) }'; then best="$s"; fi
    peaks="$(cat "$work"/peak.* | sort -n | paste -sd, -)"
  done
  printf '    "%s": {"seconds": %s, "all_seconds": [%s], "peak_kib": %s, "peak_kib_per_process": [%s]},\n' "$name" \
    "$best" "$seconds" "${peaks##*,}" "$peaks"
}
timed() { /usr/bin/time -f "%M" -o "$work/peak.single" "$@"; }
# Under mpirun: each rank's peak in peak.<rank>.
per_rank=(bash -c '/usr/bin/time -f "%M" -o "$0/peak.$OMPI_COMM_WORLD_RANK" "$@"' "$work")

echo "{"
echo "  \"tool\": \"$tool\", \"threads_per_process\": $threads, \"repeats\": $repeats, \"cores\": $(nproc),"
echo "  \"sizes\": {"
IFS=, read -ra list <<<"$sizes"
for n in "${list[@]}"; do
  length=$(awk -v n="$n" 'BEGIN { printf "%d", n / 1000000 * 400 }')
  scan="$work/street_$n.ply"
  [ -f "$scan" ] || "$tool" points generate --points "$n" --length "$length" --seed 8 -q -o "$scan" >/dev/null
  echo "  \"$n\": {"
  echo "    \"points\": $(head -c 400 "$scan" | grep -a -m1 'element vertex' | awk '{ print $3 }'),"
  common=(points recognize "$scan" --tile-size 100 --threads "$threads" -q)
  run in_memory timed "$tool" "${common[@]}" -o "$work/memory.ply" --locations "$work/memory.csv"
  run out_of_core timed "$tool" "${common[@]}" -o "$work/one.ply" --locations "$work/one.csv" --work-dir "$work/w1"
  echo "    \"work_folder_bytes\": $(du -sb "$work/w1" | cut -f1),"
  same_one=$(cmp -s "$work/memory.ply" "$work/one.ply" && cmp -s "$work/memory.csv" "$work/one.csv" && echo true || echo false)
  same_two=null
  if [ -n "$mpirun" ]; then
    run ranks_2 "$mpirun" --allow-run-as-root --oversubscribe -np 2 "${per_rank[@]}" \
      "$tool" "${common[@]}" -o "$work/two.ply" --locations "$work/two.csv" --work-dir "$work/w2"
    same_two=$(cmp -s "$work/memory.ply" "$work/two.ply" && cmp -s "$work/memory.csv" "$work/two.csv" && echo true || echo false)
  fi
  echo "    \"out_of_core_same_bytes\": $same_one, \"ranks_2_same_bytes\": $same_two"
  echo "  },"
  rm -rf "$work/w1" "$work/w2" "$work"/*.ply.tmp-* 2>/dev/null || true
done
echo "  \"end\": null"
echo "  }"
echo "}"
