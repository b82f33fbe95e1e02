# Shared by demo.sh, test.sh and test_sanitized.sh (sourced): installs the missing Debian packages
# and, unless `no_release_configure` is set, configures a Release build in build/. Sets `root`
# and `jobs`.
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/install_dependencies.sh"

# One compile job per core, but at most one per `job_memory_kb` of available memory (default
# 2 GB: a CGAL translation unit takes 1 to 2 GB; more with sanitizers).
jobs="$(nproc 2>/dev/null || echo 2)"
memory_jobs="$(awk -v per="${job_memory_kb:-2097152}" '/MemAvailable/ { print int($2 / per) }' /proc/meminfo 2>/dev/null || echo "$jobs")"
if [ "${memory_jobs:-0}" -lt 1 ]; then memory_jobs=1; fi
if [ "$memory_jobs" -lt "$jobs" ]; then jobs="$memory_jobs"; fi

if [ -z "${no_release_configure:-}" ]; then
  cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release
fi
