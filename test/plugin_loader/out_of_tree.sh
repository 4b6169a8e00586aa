#!/usr/bin/env bash
# Installs a facet build tree, builds sdk/template against the installed SDK in a separate
# directory (as a user would), and runs the template's graph with the installed `facet`.
#
# usage: out_of_tree.sh SOURCE_DIR BUILD_DIR [PROBE]
#   PROBE: optional facet_plugin_probe executable, to check the plugin loads without the CLI.
set -euo pipefail

source_dir=$1
build_dir=$2
probe=${3:-}

work=$(mktemp -d "${TMPDIR:-/tmp}/facet-out-of-tree.XXXXXX")
trap 'rm -rf "$work"' EXIT
unset FACET_PLUGIN_PATH  # only the directories given below may be searched

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

# Runs a command quietly, showing its output only when it fails.
step() {
  local name=$1
  shift
  echo "--- $name"
  if ! "$@" >"$work/step.log" 2>&1; then
    cat "$work/step.log" >&2
    fail "$name"
  fi
}

prefix=$work/prefix
step "install the build tree" cmake --install "$build_dir" --prefix "$prefix"
for file in bin/facet include/facet/plugin.hpp include/facet/sdk_version.h \
  include/facet/testing/stage_runner.hpp include/facet/types/images.hpp; do
  [[ -e $prefix/$file ]] || fail "installed tree lacks $file"
done
config=$(find "$prefix" -name facetConfig.cmake -print -quit)
[[ -n $config ]] || fail "installed tree lacks facetConfig.cmake"
[[ -e $(dirname "$config")/FacetPlugin.cmake ]] || fail "installed tree lacks FacetPlugin.cmake"

generator=()
if command -v ninja >/dev/null; then generator=(-G Ninja); fi
template_build=$work/template-build
step "configure the template against the installed SDK" \
  cmake -S "$source_dir/sdk/template" -B "$template_build" "${generator[@]}" \
  -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$prefix" \
  -DCMAKE_CXX_FLAGS="${FACET_TEMPLATE_CXX_FLAGS:-}" \
  -DCMAKE_EXE_LINKER_FLAGS="${FACET_TEMPLATE_LINKER_FLAGS:-}" \
  -DCMAKE_MODULE_LINKER_FLAGS="${FACET_TEMPLATE_LINKER_FLAGS:-}" \
  -DCMAKE_SHARED_LINKER_FLAGS="${FACET_TEMPLATE_LINKER_FLAGS:-}"
step "build the template" cmake --build "$template_build" -j 2
step "run the template's unit tests" ctest --test-dir "$template_build" --output-on-failure

plugin=$template_build/libfacet_template.so
[[ -f $plugin ]] || fail "the template build did not produce libfacet_template.so"

if [[ -n $probe ]]; then
  step "load the template plugin" "$probe" "$plugin"
  grep -q "^stage template.counter:" "$work/step.log" || fail "template.counter not registered"
  grep -q "^stage template.threshold:" "$work/step.log" || fail "template.threshold not registered"
fi

facet=$prefix/bin/facet
step "facet list" "$facet" list --plugin-path "$template_build"
grep -q "template.counter" "$work/step.log" || fail "facet list does not show template.counter"
grep -q "template.threshold" "$work/step.log" || fail "facet list does not show template.threshold"

step "facet run" "$facet" run "$source_dir/sdk/template/graph.yaml" \
  --plugin-path "$template_build" --param frames=3 --json "$work/run.json"
grep -Eq '"frames": *3\b' "$work/run.json" || fail "run.json does not report 3 frames"
# The ramp from 500 to 2000 mm cut at 1250 mm keeps exactly half of every image.
grep -A1 '"kept_ratio"' "$work/run.json" | grep -Eq '"mean": *0\.5\b' ||
  fail "run.json lacks the threshold's kept_ratio metric of 0.5"

# A program of one's own against the installed facet::runtime (examples/cpp).
example_build=$work/example-build
step "configure examples/cpp against the installed package" \
  cmake -S "$source_dir/examples/cpp" -B "$example_build" "${generator[@]}" \
  -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$prefix" \
  -DCMAKE_CXX_FLAGS="${FACET_TEMPLATE_CXX_FLAGS:-}" \
  -DCMAKE_EXE_LINKER_FLAGS="${FACET_TEMPLATE_LINKER_FLAGS:-}"
step "build examples/cpp" cmake --build "$example_build" -j 2
[[ -e $prefix/include/facet/pipeline.hpp ]] || fail "installed tree lacks facet/pipeline.hpp"
# The installed graph, with the installed plugins found beside the installed runtime library.
step "run examples/cpp" "$example_build/segment_frame" "$prefix/share/facet/graphs/tabletop.yaml" \
  "$source_dir/data/mosd/depth/learn0.png"
grep -Eq "^[1-9][0-9]* objects in" "$work/step.log" || fail "examples/cpp found no objects"
grep -q "^object 1: " "$work/step.log" || fail "examples/cpp printed no object"

# The installed Python package, when this build made one.
python_package=$(find "$prefix" -path "*/facet/__init__.py" -print -quit)
if [[ -n $python_package ]]; then
  step "import the installed Python package" env PYTHONPATH="$(dirname "$(dirname "$python_package")")" \
    "${FACET_TEST_PYTHON:-python3}" -c "import facet; names = [s['name'] for s in facet.stages()]; assert 'partition.graph' in names, names; print('python: OK')"
fi

echo "out-of-tree template: OK"
