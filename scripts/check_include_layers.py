#!/usr/bin/env python3
"""Checks the include arrows of the library's headers.

Reads every `#include <CGAL_ext/...>` of include/CGAL_ext and fails (exit 1,
naming each arrow) where

* a header includes one of a higher layer (the layers are below: an arrow
  runs from a layer to the same layer or a lower one), or
* a header includes an `X/internal/` header (the engine of family X) from
  outside family X, without being of a higher layer than it: a family's
  engine serves its family and what is built on the family, never a
  neighbour of its layer.

A header that no layer names fails too, so that a new folder is placed
before it is used; so does a public header (one outside every internal/
folder) more than a third of whose lines are `namespace internal` code: a
public header shows the interface, its family's internal/ the engine. Usage: python3 scripts/check_include_layers.py [root],
root being the repository (by default, the one this script is in).
"""

import os
import re
import sys

# Paths relative to include/CGAL_ext, first match wins: (pattern, layer, what).
LAYERS = [
    # 0: core utilities, which know nothing of the mesh.
    (r"internal/[^/]+\.h", 0, "core utilities"),
    (r"(exceptions|Named_parameters|Sharp_feature_options|Mobius_mesh/Vertex_normal_weighting)\.h", 0, "core"),
    # 2, ahead of the rest of Mobius_mesh/internal/: the checks of a collapse
    # are built on the Euler operations, and serve the algorithms that collapse
    # (with the rules of the corner channels through collapses, splits and moves).
    # So are the engines of the mesh algorithms of Mobius_mesh/ that build on
    # other mesh algorithms (the Euler operations, copies, the topology).
    (r"Mobius_mesh/internal/(Collapse_checks|Corner_channel_edits|Fan_triangulation|Shape_builders|Soup_import|Mesh_copy|Two_sided_geometry|Normal_transformation)\.h", 2,
     "mesh algorithms"),
    # 1: the mesh and its internals.
    (r"Mobius_mesh\.h", 1, "mesh"),
    (r"Mobius_mesh/internal/[^/]+\.h", 1, "mesh"),
    # 2: the algorithms on the mesh that every family builds on. The
    # sharpness maps and the soup import are such algorithms, with the paths
    # of top-level public headers.
    (r"Mobius_mesh/[^/]+\.h", 2, "mesh algorithms"),
    (r"boost/graph/([^/]+|internal/[^/]+)\.h", 2, "mesh algorithms"),
    (r"(Sharp_features|polygon_soup_to_mobius_mesh)\.h", 2, "mesh algorithms"),
    # 3: the algorithm families, each in its folder with its internal/.
    (r"(Subdivision|Merging|Conversion|Decimation|Remeshing|Offset|IO|Geodesics|Curvature|Hole_filling|Smoothing|"
     r"Polygon_mesh_processing)/([^/]+|internal/[^/]+)\.h", 3, "families"),
    # 4, with the top-level headers: families built on another family's
    # public entry (the limit surface refines a face's neighbourhood with
    # subdivision.h).
    (r"(Limit_surface)/([^/]+|internal/[^/]+)\.h", 4, "families on families"),
    # 4: the top-level public headers, each the entry of a family.
    (r"[^/]+\.h", 4, "top-level public headers"),
]

INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]CGAL_ext/([^>"]+)[>"]')


def layer_of(path):
    for pattern, layer, what in LAYERS:
        if re.fullmatch(pattern, path):
            return layer, what
    return None


def family_of(path):
    """The folder a header belongs to ('' for the top level and the core's
    internal/); a top-level header that is a folder's entry belongs to it:
    Mobius_mesh.h and Limit_surface.h, and the mesh algorithms with top-level
    paths (the soup import, the sharpness maps) to Mobius_mesh/."""
    if path.startswith("internal/"):
        return ""
    if path.startswith("boost/graph/"):
        return "boost/graph"
    if "/" in path:
        return path.split("/", 1)[0]
    entries = {"Mobius_mesh.h": "Mobius_mesh", "Limit_surface.h": "Limit_surface",
               "polygon_soup_to_mobius_mesh.h": "Mobius_mesh", "Sharp_features.h": "Mobius_mesh",
               "offset_mesh.h": "Offset"}
    return entries.get(path, "")


def internal_family(path):
    """X for a header of X/internal/ ('' for internal/), else None."""
    parts = path.split("/")
    if len(parts) >= 2 and parts[-2] == "internal":
        return "/".join(parts[:-2])
    return None


INTERNAL_OPEN = re.compile(r"^namespace internal \{")
INTERNAL_CLOSE = re.compile(r"^\} // namespace internal")


def internal_share(lines):
    """The share of `lines` inside top-level `namespace internal` blocks."""
    inside, count = False, 0
    for line in lines:
        if INTERNAL_OPEN.match(line):
            inside = True
        if inside:
            count += 1
        if INTERNAL_CLOSE.match(line):
            inside = False
    return count / max(len(lines), 1)


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
    base = os.path.join(root, "include", "CGAL_ext")
    headers = []
    for folder, _, files in os.walk(base):
        for name in files:
            if name.endswith(".h"):
                headers.append(os.path.relpath(os.path.join(folder, name), base).replace(os.sep, "/"))
    headers.sort()

    problems = []
    for path in headers:
        if layer_of(path) is None:
            problems.append(f"CGAL_ext/{path}: in no layer (add it to LAYERS in {os.path.basename(__file__)})")
    arrows = 0
    for path in headers:
        here = layer_of(path)
        if here is None:
            continue
        with open(os.path.join(base, path), encoding="utf-8") as f:
            lines = f.read().split("\n")
        if internal_family(path) is None and internal_share(lines) > 1 / 3:
            problems.append(f"CGAL_ext/{path}: {internal_share(lines):.0%} of its lines are internal code "
                            f"(a third at most: move the engine to its family's internal/)")
        for number, line in enumerate(lines, 1):
            m = INCLUDE.match(line)
            if not m:
                continue
            arrows += 1
            target = m.group(1)
            there = layer_of(target)
            where = f"CGAL_ext/{path}:{number}: CGAL_ext/{path} -> CGAL_ext/{target}"
            if there is None:
                problems.append(f"{where}: the included header is in no layer")
                continue
            if there[0] > here[0]:
                problems.append(f"{where}: upward, from layer {here[0]} ({here[1]}) to layer "
                                f"{there[0]} ({there[1]})")
            owner = internal_family(target)
            if owner is not None and family_of(path) != owner and here[0] <= there[0]:
                problems.append(f"{where}: the engine of {owner or 'the core'}/ included from "
                                f"{family_of(path) or 'the top level'}, a neighbour of its layer")

    for p in problems:
        print(f"include layers: {p}", file=sys.stderr)
    if problems:
        print(f"include layers: {len(problems)} problem(s) in {arrows} include arrows of {len(headers)} headers",
              file=sys.stderr)
        return 1
    print(f"include layers: {arrows} include arrows of {len(headers)} headers, none upward; "
          "no public header over a third internal")
    return 0


if __name__ == "__main__":
    sys.exit(main())
