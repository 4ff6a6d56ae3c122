#!/usr/bin/env python3
"""Checks that the folders of each given tree include one another one way only.

  include_layers.py SOURCE_DIR core render

Every #include "a/b/file.h" of a file in folder a/x naming a file in a sibling folder a/b is an
edge x -> b. Folders whose edges form a cycle (a folder that includes one that, directly or
through others, includes it back) are listed with the includes that close each cycle, and the
check exits 1; with no cycle it exits 0.
"""
import os
import re
import sys

INCLUDE = re.compile(r'^[ \t]*#[ \t]*include[ \t]*"([^"]+)"', re.M)
SOURCES = (".h", ".hpp", ".cpp", ".cc")


def folder_edges(source_dir, tree):
    """{folder: {included folder: [(file, include), ...]}} between the folders of one tree."""
    edges = {}
    top = os.path.join(source_dir, tree)
    for folder in sorted(os.listdir(top)):
        if not os.path.isdir(os.path.join(top, folder)):
            continue
        for root, _, files in os.walk(os.path.join(top, folder)):
            for name in sorted(files):
                if not name.endswith(SOURCES):
                    continue
                path = os.path.join(root, name)
                with open(path, encoding="utf-8", errors="replace") as f:
                    text = f.read()
                for included in INCLUDE.findall(text):
                    parts = included.split("/")
                    if len(parts) < 3 or parts[0] != tree or parts[1] == folder:
                        continue
                    if not os.path.exists(os.path.join(source_dir, included)):
                        continue  # a generated header or one of another root
                    rel = os.path.relpath(path, source_dir)
                    edges.setdefault(folder, {}).setdefault(parts[1], []).append((rel, included))
    return edges


def cycles(edges):
    """The strongly connected components with more than one folder (Tarjan)."""
    index, low, stack, on_stack, found = {}, {}, [], set(), []

    def visit(v):
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in edges.get(v, {}):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    for v in sorted(edges):
        if v not in index:
            visit(v)
    return found


def cycle_through(edges, component):
    """One shortest cycle through the component's first folder, as a list of folders."""
    start = component[0]
    paths = {start: [start]}
    queue = [start]
    while queue:
        v = queue.pop(0)
        for w in sorted(edges.get(v, {})):
            if w == start:
                return paths[v] + [start]
            if w in component and w not in paths:
                paths[w] = paths[v] + [w]
                queue.append(w)
    return [start]


def main(argv):
    if len(argv) < 3:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    source_dir, trees = argv[1], argv[2:]
    failed = False
    for tree in trees:
        edges = folder_edges(source_dir, tree)
        found = cycles(edges)
        for component in found:
            failed = True
            print(f"{tree}: folders that include each other: {', '.join(component)}; for one:")
            path = cycle_through(edges, component)
            for a, b in zip(path, path[1:]):
                rel, included = edges[a][b][0]
                print(f"  {tree}/{a} -> {tree}/{b}: {rel} includes {included}")
        if not found:
            print(f"{tree}: {len(edges)} folders include others, one way")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
