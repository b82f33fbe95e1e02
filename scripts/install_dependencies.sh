#!/usr/bin/env bash
# Installs the Debian 12 packages this project needs that are missing (idempotent).
# Usage: scripts/install_dependencies.sh [extra packages...]
set -euo pipefail

packages=(
  cmake make g++ ccache
  libcgal-dev libcgal-demo        # CGAL 5.5 headers; its data archive (meshes used by tests and demo)
  libeigen3-dev libboost-dev libtbb-dev libgmp-dev libmpfr-dev
  libgeographiclib-dev libgtest-dev libcli11-dev
  "$@"
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if [ ${#missing[@]} -eq 0 ]; then
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
