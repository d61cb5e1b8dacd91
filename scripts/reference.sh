#!/usr/bin/env bash
# Builds the API reference (Doxygen, HTML) into build/reference/html and
# fails on any Doxygen warning: an undocumented public class, function or
# member, a broken reference, or a named parameter of
# include/CGAL_ext/internal/parameters_interface.h missing from
# doc/named_parameters.md.
set -euo pipefail
cd "$(dirname "$0")/.."
command -v doxygen >/dev/null 2>&1 || { echo "reference: doxygen is not installed (bash scripts/install-deps.sh)" >&2; exit 2; }

out=${CGAL_EXT_REFERENCE_DIR:-build/reference}
mkdir -p "$out"
missing=0
for name in $(sed -nE 's/^CGAL_EXT_add_named_parameter\([^,]*,[^,]*, *([a-z_]+)\)/\1/p' include/CGAL_ext/internal/parameters_interface.h); do
  if ! grep -q "^| \`$name\`" doc/named_parameters.md; then
    echo "reference: named parameter '$name' is not documented in doc/named_parameters.md" >&2
    missing=1
  fi
done
CGAL_EXT_REFERENCE_DIR="$out" doxygen doc/Doxyfile
[ "$missing" -eq 0 ]
echo "reference: $out/html/index.html"
