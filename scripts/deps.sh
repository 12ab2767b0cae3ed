#!/usr/bin/env bash
# Installs the Debian packages Tessel builds and tests with. Idempotent: prints nothing and
# touches nothing when everything is already present.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config ccache
  # the format check of make test (scripts/check_format.sh)
  clang-format
  libglm-dev libstb-dev libcli11-dev nlohmann-json3-dev libtinyobjloader-dev libtinygltf-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  # the GLSL front end and the shader JIT (src/glsl)
  glslang-dev glslang-tools llvm-15-dev
  # the libFuzzer targets (scripts/fuzz.sh)
  clang libclang-rt-14-dev
  # the reference oracle: Mesa llvmpipe through EGL (surfaceless) and desktop GL
  libegl-dev libegl-mesa0 libgl1-mesa-dri libgl-dev libopengl-dev libosmesa6-dev
  # GLUT windows (SDL2), and the GL 1.x comparison tests: each program built against Mesa's
  # libGL, libGLU and freeglut runs under Xvfb
  libsdl2-dev libx11-dev freeglut3-dev libglu1-mesa-dev xvfb xauth
  # the GL 3.3 comparison tests: GLEW and GLFW on the Mesa side
  libglew-dev libglfw3-dev
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "deps.sh: installing ${missing[*]}"
SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
