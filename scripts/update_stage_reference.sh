#!/usr/bin/env bash
# Regenerates the part of docs/stage-reference.md below its marker from the built stages.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
page="$here/docs/stage-reference.md"
marker='<!-- generated below: do not edit by hand -->'
header="$(sed "/$marker/q" "$page")"
{ printf '%s\n\n' "$header"; "$here/build/bin/facet" inspect --all --markdown; } > "$page.tmp"
mv "$page.tmp" "$page"
