#!/usr/bin/env bash
# Installs every Debian (bookworm) package Kerf needs to build, test and run. Idempotent: packages that
# are already present are skipped, so a second run costs a few seconds and no network.
set -euo pipefail

packages=(
  # toolchain
  build-essential cmake ninja-build pkg-config clang-format ccache
  # scripts/check-folder-graph.py (standard library only)
  python3-minimal
  # core libraries
  libglm-dev libeigen3-dev libceres-dev libopencv-dev libopenimageio-dev openimageio-tools libpng-dev libstb-dev
  nlohmann-json3-dev libcli11-dev
  # OpenVDB volume export; Debian's find module also needs Boost.Iostreams, which the package does not pull in
  libopenvdb-dev libboost-iostreams-dev
  # textured parts: meshes read with assimp, binary glTF written with tinygltf
  libassimp-dev libtinygltf-dev
  # tests and benchmarks
  libgtest-dev libgmock-dev libbenchmark-dev
  # Qt 6 (Widgets, OpenGL, OpenGLWidgets, Concurrent, Test) and its X11 platform plugin
  qt6-base-dev qt6-base-dev-tools qt6-qpa-plugins libqt6opengl6-dev libgl-dev libglx-dev
  # headless GUI tests: a virtual X server and Mesa's software OpenGL (llvmpipe)
  xvfb xauth libgl1-mesa-dri libglx-mesa0 mesa-utils fonts-dejavu-core
)

# --training: also what scripts/train_ring_detector.py needs (PyTorch from Debian). Not needed to build,
# test or run Kerf: the trained network ships in resources/models.
if [ "${1:-}" = "--training" ]; then
  packages+=(python3-torch python3-opencv python3-numpy)
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages already installed"
  exit 0
fi

echo "install-deps: installing ${#missing[@]} packages: ${missing[*]}"
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install-deps: done"
