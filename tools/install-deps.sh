#!/usr/bin/env bash
# Installs the Debian packages clothtear needs, skipping the ones already present.
# Usage: tools/install-deps.sh [--no-app]   (as root, or with sudo available)
set -euo pipefail
packages=(cmake ninja-build g++ pkg-config libeigen3-dev libgtest-dev libgmock-dev libbenchmark-dev
          libcli11-dev nlohmann-json3-dev libtinyobjloader-dev
          libbullet-dev       # Bullet: only clothbench's peers mode uses it (the build skips it when missing)
          clang-14 libclang-rt-14-dev  # clang and libFuzzer for tools/fuzz.sh
          python3)            # tools/mutate.sh (its --check is a test) and the gesture scripts
if [[ "${1:-}" != "--no-app" ]]; then
  packages+=(libglfw3-dev libglew-dev libimgui-dev libstb-dev libsdl2-dev xvfb xauth) # SDL2: the app's live sound
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "clothtear: installing ${missing[*]}"
  SUDO=""; [[ $(id -u) -ne 0 ]] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
