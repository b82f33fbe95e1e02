#!/usr/bin/env bash
# `points recognize` out of core on one scan of any size (a file or a folder of tiles, such as the
# 10^9 points of `points generate --points 1000000000 --length 400000 -o street.las`), the whole
# command timed, with the peak resident memory of each process (GNU time's %M) and the phases the
# report gives (indexing, tiles, merging, the rest is writing). Only the objects' points are
# written (--only-objects: the whole scan written back would double the disk it takes); with RANKS
# above 1, under `mpirun -np RANKS` (the work folder shared); with MODEL (a model of `points train`),
# the objects are classified too.
#
#   bench/recognize_scan.sh TOOL SCAN [THREADS=0] [RANKS=1] [MODEL=] [WORK=a temporary folder]  -> JSON on stdout
#
# Needs GNU time (/usr/bin/time) and, for RANKS > 1, mpirun.
set -euo pipefail
tool="$1"
scan="$2"
threads="${3:-0}"
ranks="${4:-1}"
model="${5:-}"
work="${6:-$(mktemp -d)}"
mkdir -p "$work"
[ -n "${6:-}" ] || trap 'rm -rf "$work"' EXIT
rm -rf "$work/w" "$work"/peak.* "$work/objects.las" "$work/report.json"
args=(points recognize "$scan" --work-dir "$work/w" --only-objects --threads "$threads" -q -o "$work/objects.las"
      --locations "$work/locations.csv" --report "$work/report.json")
[ -z "$model" ] || args+=(--model "$model")
t0="$(date +%s.%N)"
if [ "$ranks" -gt 1 ]; then
  mpirun --allow-run-as-root --oversubscribe --bind-to none -np "$ranks" \
    bash -c '/usr/bin/time -f "%M" -o "$0/peak.$OMPI_COMM_WORLD_RANK" "$@"' "$work" "$tool" "${args[@]}" >/dev/null
else
  /usr/bin/time -f "%M" -o "$work/peak.0" "$tool" "${args[@]}" >/dev/null
fi
t1="$(date +%s.%N)"
python3 - "$work" "$scan" "$ranks" "$threads" "$model" "$t0" "$t1" <<'PY'
import glob, json, os, subprocess, sys
work, scan, ranks, threads, model, t0, t1 = sys.argv[1:8]
r = json.load(open(os.path.join(work, "report.json")))
peaks = sorted(int(open(p).read().split()[-1]) for p in glob.glob(os.path.join(work, "peak.*")))
seconds = float(t1) - float(t0)
n = r.get("number_of_points", 0)
du = lambda p: int(subprocess.check_output(["du", "-sb", p]).split()[0])
print(json.dumps({
    "scan": scan, "scan_bytes": du(scan), "ranks": int(ranks), "threads_per_rank": int(threads),
    "classified": bool(model), "points": n, "seconds": round(seconds, 3),
    "points_per_second": round(n / seconds) if seconds > 0 else None,
    "peak_kib_per_rank": peaks,
    "phases": {k: round(r[k], 3) for k in ("seconds_indexing", "seconds_tiles", "seconds_merging", "seconds_total") if k in r},
    "tiles": len(r.get("tiles", [])), "objects": len(r.get("objects", [])),
    "output_bytes": du(os.path.join(work, "objects.las")), "work_folder_bytes": du(os.path.join(work, "w")),
}, indent=2))
PY
