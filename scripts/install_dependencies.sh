#!/usr/bin/env bash
# Installs the Debian 12 packages this project needs that are missing (idempotent).
# Usage: scripts/install_dependencies.sh [extra packages...]
set -euo pipefail

packages=(
  cmake make g++ ccache
  libcgal-dev libcgal-demo        # CGAL 5.5 headers; its data archive (meshes used by tests and demo)
  libeigen3-dev libboost-dev libtbb-dev libgmp-dev libmpfr-dev
  libgtest-dev libcli11-dev nlohmann-json3-dev
  libsvm-dev                       # Svm_object_classifier
  libosmium2-dev libexpat1-dev zlib1g-dev libgeographiclib-dev  # street maps (OpenStreetMap, UTM)
  openmpi-bin libopenmpi-dev       # points recognize on the ranks of an MPI job (optional in CMake)
  python3                         # scripts/check_*.py (sizes, package dependencies), run by ctest
  doxygen libjs-mathjax           # the manual, built and checked (0 warnings) by ctest
  "$@"
)

# Images that leave /usr/share/doc out of packages (dpkg path-exclude) install libcgal-demo without
# its data archive: take the archive from the package file itself. This script is the one place
# the project installs or downloads anything; CMake only reads the archive.
restore_cgal_data() {
  local archive=/usr/share/doc/libcgal-dev/data.tar.gz
  if [ -f "$archive" ] || ! dpkg-query -W -f='${Status}' libcgal-demo 2>/dev/null | grep -q "install ok installed"; then
    return 0
  fi
  if [ "$(id -u)" -ne 0 ]; then
    echo "warning: $archive is missing; run this script as root to restore it" >&2
    return 0
  fi
  local dir
  dir="$(mktemp -d)"
  echo "Restoring $archive from the libcgal-demo package" >&2
  (cd "$dir" && apt-get download -qq libcgal-demo >/dev/null 2>&1) || apt-get update -qq
  (cd "$dir" && ls libcgal-demo*.deb >/dev/null 2>&1 || apt-get download -qq libcgal-demo >/dev/null)
  dpkg-deb --fsys-tarfile "$dir"/libcgal-demo*.deb | tar -x -C / ./usr/share/doc/libcgal-dev/data.tar.gz
  rm -rf "$dir"
}

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if [ ${#missing[@]} -eq 0 ]; then
  restore_cgal_data
  exit 0
fi

echo "Installing missing Debian packages: ${missing[*]}" >&2
if [ "$(id -u)" -eq 0 ]; then
  sudo_cmd=()
elif command -v sudo >/dev/null 2>&1; then
  sudo_cmd=(sudo -n) # never wait for a password (CI)
else
  echo "error: missing packages (${missing[*]}) and not root; install them with apt-get" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
restore_cgal_data
