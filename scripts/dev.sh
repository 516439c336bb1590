#!/usr/bin/env bash
# glyphfair's one entry point on a fresh Debian 12 machine (root, apt reachable):
#   scripts/dev.sh demo   install what is missing, build, run the main job (out/)
#   scripts/dev.sh test   install what is missing, build, run the whole test suite
#   scripts/dev.sh bench  install what is missing, build, run the benchmarks
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  g++ cmake make pkg-config
  libfreetype-dev libharfbuzz-dev libcairo2-dev libeigen3-dev libboost-dev
  libcli11-dev nlohmann-json3-dev libpugixml-dev libtbb-dev
  libgtest-dev libbenchmark-dev
  # independent checkers used by the tests: fontTools' ufoLib, fontmake
  python3-fonttools fontmake python3-jsonschema python3-scipy
)

install_missing() {
  local missing=() p
  for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
  done
  ((${#missing[@]} == 0)) && return 0
  echo "installing: ${missing[*]}"
  local sudo=(); ((EUID == 0)) || sudo=(sudo)
  export DEBIAN_FRONTEND=noninteractive
  "${sudo[@]}" apt-get update -qq
  "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
}

build() {
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
  if ! cmake --build build -j"$(nproc)" >build/build.log 2>&1; then
    cat build/build.log >&2; echo "build failed" >&2; exit 1
  fi
}

demo() {
  local font=fonts/BecauseWeLearn/BecauseWeLearn-Regular-subset.otf
  mkdir -p out
  build/glyphfair fair "$font" --profile handwriting --text "Hamburgefonstiv" \
    -o out/handwriting-faired.ufo --proof out/handwriting-proof.pdf
  echo "wrote out/handwriting-faired.ufo and out/handwriting-proof.pdf (faired in black, the source in red)"
}

case "${1:-}" in
  demo)  install_missing; build; demo ;;
  test)  install_missing; build; ctest --test-dir build --output-on-failure -j"$(nproc)" ;;
  bench) install_missing; build; scripts/bench.sh ;;
  *) echo "usage: scripts/dev.sh demo|test|bench" >&2; exit 2 ;;
esac
