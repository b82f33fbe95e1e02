#!/usr/bin/env bash
# Builds the tool and the tests with AddressSanitizer and UndefinedBehaviorSanitizer (-O1, in
# build-asan/; examples and benchmarks left out) and runs the unit tests and the bad-input
# catalogue under them: any report fails its test. Installs missing Debian packages first.
# Usage: scripts/test_sanitized.sh [ctest arguments...]
set -euo pipefail
no_release_configure=1
job_memory_kb=3145728
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
# Without MPI: Open MPI's own allocations at MPI_Init are leaks to LeakSanitizer (the ranks' tests
# run in scripts/test.sh's build; the work-folder path they share runs here on one process).
cmake -S "$root" -B "$root/build-asan" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" -DSHAPE_ANALYSIS_SANITIZE=ON \
  -DSHAPE_ANALYSIS_BUILD_EXAMPLES=OFF -DSHAPE_ANALYSIS_BUILD_BENCHMARKS=OFF -DSHAPE_ANALYSIS_WITH_MPI=OFF
cmake --build "$root/build-asan" --parallel "$jobs"
cd "$root/build-asan"
# Leaks are reported too; a report stops the program with status 86 (no test expects it).
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0:exitcode=86"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:exitcode=86"
ctest --output-on-failure --parallel "$jobs" "$@"
