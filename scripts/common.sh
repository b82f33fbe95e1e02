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
# nproc counts the processors of the affinity mask, not a cgroup CPU quota (a container started
# with --cpus 2 on a large host): at most one job per processor of the quota (v2, then v1).
quota_jobs=""
if [ -r /sys/fs/cgroup/cpu.max ]; then
  quota_jobs="$(awk '$1 != "max" && $2 > 0 { q = $1 / $2; n = int(q); if (n < q) n++; if (n < 1) n = 1; print n }' /sys/fs/cgroup/cpu.max 2>/dev/null || true)"
elif [ -r /sys/fs/cgroup/cpu/cpu.cfs_quota_us ] && [ -r /sys/fs/cgroup/cpu/cpu.cfs_period_us ]; then
  quota_jobs="$(awk 'NR == FNR { q = $1; next } q > 0 && $1 > 0 { r = q / $1; n = int(r); if (n < r) n++; if (n < 1) n = 1; print n }' \
                /sys/fs/cgroup/cpu/cpu.cfs_quota_us /sys/fs/cgroup/cpu/cpu.cfs_period_us 2>/dev/null || true)"
fi
if [ -n "$quota_jobs" ] && [ "$quota_jobs" -lt "$jobs" ]; then jobs="$quota_jobs"; fi
echo "scripts: $jobs parallel jobs (nproc $(nproc 2>/dev/null || echo '?'), cgroup CPU quota ${quota_jobs:-none}, memory for ${memory_jobs})"

if [ -z "${no_release_configure:-}" ]; then
  cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release
fi
