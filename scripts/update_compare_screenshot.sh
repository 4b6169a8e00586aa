#!/usr/bin/env bash
# Replaces docs/images/compare-report.png, the report screenshot in docs/compare.md, by the one
# the tests take: CompareReportInChromium runs the command docs/compare.md quotes above the
# picture, draws its report in headless Chromium, checks the screenshot and, with
# FACET_SCREENSHOT_DIR set, copies it there. Needs chromium (Debian package 'chromium').
#
#   scripts/update_compare_screenshot.sh [BUILD_DIR]     (default: build)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
build_dir=${1:-build}
command -v chromium > /dev/null || { echo "chromium is not installed" >&2; exit 1; }
# The test program depends on the CLI and the bundled plugins: all of them are current after this.
cmake --build "$build_dir" --target facet_cli_tests
FACET_SCREENSHOT_DIR="$PWD/docs/images" "$build_dir/bin/facet_cli_tests" \
  --gtest_filter='CompareReportInChromium.*'
git status --short docs/images/compare-report.png
