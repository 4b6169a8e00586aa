#!/usr/bin/env bash
# Runs facet's libFuzzer targets (fuzz/), each for SECONDS (default 60), on a working copy of its
# seed corpus (fuzz/corpus/<name>/, grown in build-fuzz/corpus/<name>/ and kept between runs).
#
#   scripts/fuzz.sh [SECONDS] [NAME...]     NAME: png pcd_header graph intrinsics tum_list
#
# Builds the fuzz targets of the `fuzz` preset first (clang-14, ASan + UBSan). A finding (crash,
# hang over 10 s, allocation over 1 GiB, sanitizer report) is written to
# build-fuzz/findings/<name>-*, the script says which and exits 1. Reproduce one with:
# build-fuzz/bin/facet_fuzz_<name> <file>.
# FACET_FUZZ_SEED fixes libFuzzer's random seed (CI sets 1); unset, every run explores anew.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
seconds="${1:-60}"
shift || true
names=("$@")
[ ${#names[@]} -eq 0 ] && names=(png pcd_header graph intrinsics tum_list)

cmake --preset fuzz >/dev/null
# Only what the fuzz targets link: the plugins and the CLI are not needed here, and building them
# with clang and ASan would double the time of a cold CI run.
cmake --build --preset fuzz -j "$(nproc)" --target facet_fuzzers

mkdir -p build-fuzz/findings
status=0
for name in "${names[@]}"; do
  target="build-fuzz/bin/facet_fuzz_${name}"
  [ -x "$target" ] || { echo "no fuzz target '$name'" >&2; exit 2; }
  corpus="build-fuzz/corpus/${name}"
  mkdir -p "$corpus"
  before=$(find build-fuzz/findings -name "${name}-*" | wc -l)
  echo "fuzzing ${name} for ${seconds} s"
  # Leaks are findings too; the limits turn exhaustion into a finding instead of a slow machine.
  ASAN_OPTIONS="detect_leaks=1:allocator_may_return_null=0" \
    "$target" "$corpus" "fuzz/corpus/${name}" -max_total_time="$seconds" -timeout=10 \
    -rss_limit_mb=2048 -malloc_limit_mb=1024 -seed="${FACET_FUZZ_SEED:-0}" -print_final_stats=1 \
    -artifact_prefix="build-fuzz/findings/${name}-" 2>"build-fuzz/${name}.log" || true
  grep -E "^(#[0-9]+.*DONE|stat::number_of_executed_units|stat::peak_rss_mb)" \
    "build-fuzz/${name}.log" || true
  after=$(find build-fuzz/findings -name "${name}-*" | wc -l)
  if [ "$after" -gt "$before" ]; then
    echo "FINDING in ${name}: see build-fuzz/${name}.log and build-fuzz/findings/${name}-*" >&2
    grep -m3 -E "ERROR|SUMMARY|==[0-9]+==" "build-fuzz/${name}.log" >&2 || true
    status=1
  fi
done
exit $status
