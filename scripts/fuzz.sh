#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (AddressSanitizer + UndefinedBehaviorSanitizer) in
# build-fuzz/ and runs each for SECONDS (default 60) on a copy of its corpus in tests/fuzz/.
# New crashing inputs are left in build-fuzz/; the exit status is non-zero if any target failed.
# FUZZ_SEED fixes libFuzzer's seed (make test sets 1, so CI explores the same inputs each run);
# unset, each run explores new ones.
#   scripts/fuzz.sh [SECONDS] [TARGET...]
set -euo pipefail
seconds=${1:-60}
root=$(cd "$(dirname "$0")/.." && pwd)
build=${TESSEL_FUZZ_BUILD:-$root/build-fuzz}
if ! command -v clang++ >/dev/null; then
  echo "fuzz.sh: clang++ is needed (scripts/deps.sh installs it)" >&2
  exit 1
fi
CC=clang CXX=clang++ cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DTESSEL_FUZZ=ON -DTESSEL_SANITIZE=ON -DTESSEL_BUILD_BENCH=OFF \
  -DCMAKE_CXX_COMPILER_LAUNCHER="$(command -v ccache || true)" >/dev/null
cmake --build "$build" -j "${JOBS:-2}" --target fuzz_scene_file fuzz_obj fuzz_gltf fuzz_image fuzz_glsl
shift || true
targets=${*:-scene_file obj gltf image glsl}
seed_arg=()
[[ -n ${FUZZ_SEED:-} ]] && seed_arg=(-seed="$FUZZ_SEED")
status=0
for t in $targets; do
  work=$(mktemp -d)
  cp -r "$root/tests/fuzz/corpus/$t/." "$work/"
  echo "fuzz.sh: fuzz_$t for ${seconds}s"
  if ! (cd "$build" && "$build/tests/fuzz/fuzz_$t" -max_total_time="$seconds" -max_len=8192 -rss_limit_mb=3072 \
          -timeout=20 -print_final_stats=1 "${seed_arg[@]}" "$work" 2>&1 | tail -n 12); then
    status=1
  fi
  rm -rf "$work"
done
exit $status
