#!/usr/bin/env bash
# Builds everything (Release, in build/) and runs the tests. Installs missing Debian packages first.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

cmake --build "$root/build" --parallel "$jobs"
cd "$root/build"
ctest --output-on-failure --parallel "$jobs"
