# Shared by demo.sh and test.sh (sourced): installs the missing Debian packages and configures a
# Release build in build/. Sets `root` and `jobs`.
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/install_dependencies.sh"

# One compile job per core, but at most one per 2 GB of available memory (a CGAL translation
# unit takes 1 to 2 GB).
jobs="$(nproc 2>/dev/null || echo 2)"
memory_jobs="$(awk '/MemAvailable/ { print int($2 / 2097152) }' /proc/meminfo 2>/dev/null || echo "$jobs")"
if [ "${memory_jobs:-0}" -lt 1 ]; then memory_jobs=1; fi
if [ "$memory_jobs" -lt "$jobs" ]; then jobs="$memory_jobs"; fi

cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release
