#!/usr/bin/env bash
# facet quick start: install what the build needs (Debian 12), build a Release tree with the
# `release` CMake preset (Ninja, ccache when present) and then
#   scripts/quickstart.sh run    run the main job, graphs/tabletop.yaml, on the bundled frames
#   scripts/quickstart.sh test   run the whole test suite (ctest over GoogleTest)
#   scripts/quickstart.sh asan   build with AddressSanitizer + UBSan (preset `asan`) and run the suite
#   scripts/quickstart.sh tsan   build with ThreadSanitizer (preset `tsan`) the programs that run
#                                threads (SDK, executors, the runtime API) and run them
#   scripts/quickstart.sh fuzz [SECONDS]  build the libFuzzer targets (preset `fuzz`, clang) and
#                                run each for SECONDS (default 30; scripts/fuzz.sh)
# The sanitizer presets register each test program as one CTest test (FACET_TEST_PER_PROGRAM):
# under a sanitizer a process takes seconds to start, and the suite has over a thousand cases.
# (tsan leaves function entry/exit uninstrumented: the ifunc resolvers of the AVX2 kernels run
# before the sanitizer's symbols are bound; a report then shows the racing accesses, not callers)
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"
mode="${1:-run}"

# Debian packages the build and the tests need.
packages=(
  g++ cmake ninja-build pkg-config ccache
  libboost-dev libboost-filesystem-dev libyaml-cpp-dev libopencv-dev
  libeigen3-dev libcli11-dev libfmt-dev libgtest-dev libgmock-dev libbenchmark-dev libpcl-dev
  libdeflate-dev
  libopenni2-dev libopencv-highgui-dev libxcb1-dev xvfb
  cyclonedds-dev cyclonedds-tools
  chromium
  pybind11-dev python3-dev python3-numpy python3-pytest python3-opencv python3-matplotlib
)

install_packages() {
  local missing=()
  for package in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" ||
      missing+=("$package")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "installing: ${missing[*]}"
  local sudo=()
  [ "$(id -u)" -ne 0 ] && sudo=(sudo)
  "${sudo[@]}" apt-get update -q
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -q --no-install-recommends \
    "${missing[@]}"
}

build() {
  local preset="$1"
  cmake --preset "$preset"
  cmake --build --preset "$preset" -j "$(nproc)"
}

case "$mode" in
  run)
    install_packages
    build release
    build/bin/facet run graphs/tabletop.yaml --param output=out/tabletop --profile
    echo "results: out/tabletop"
    ;;
  test)
    install_packages
    build release
    ctest --preset release -j "$(nproc)"
    ;;
  asan)
    install_packages
    build asan
    ctest --preset asan -j "$(nproc)"
    ;;
  tsan)
    install_packages
    # What starts threads: parallel_for and the workspace pool (SDK), the sequential and the
    # pipelined executor (also on graphs/tabletop.yaml against each other), two Pipelines at once.
    threaded=(facet_sdk_tests facet_executor_tests facet_runtime_tests)
    cmake --preset tsan
    cmake --build --preset tsan -j "$(nproc)" --target "${threaded[@]}"
    ctest --preset tsan -j "$(nproc)" -R "^($(IFS='|'; echo "${threaded[*]}"))\$"
    ;;
  fuzz)
    # libFuzzer comes with clang's runtime libraries.
    packages+=(clang-14 libclang-rt-14-dev)
    install_packages
    # A fixed seed: the same inputs on every CI run, so a red run is a finding, not a chance.
    FACET_FUZZ_SEED=1 scripts/fuzz.sh "${2:-30}"
    ;;
  *)
    echo "usage: scripts/quickstart.sh run|test|asan|tsan|fuzz [SECONDS]" >&2
    exit 2
    ;;
esac
