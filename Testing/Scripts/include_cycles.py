#!/usr/bin/env python3
# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""Fails on an include cycle among the files of a folder (Module/ by default).

A component is a header with its source (vtkIceMapper.h and vtkIceMapper.cxx); component A
depends on B when a file of A includes "B.h". A cycle among components is what makes a change in
one of them recompile, and be understood only with, all the others of the cycle.

usage: include_cycles.py [FOLDER]   prints a cycle of each group of components that depend on
    each other ("cycle: a -> b -> a") and exits 1
"""
import os
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.MULTILINE)


def components(folder):
    """{component: its files}: the .h and .cxx files under folder, by name without extension."""
    found = {}
    for root, _, files in os.walk(folder):
        for name in files:
            stem, ext = os.path.splitext(name)
            if ext in (".h", ".cxx", ".cpp"):
                found.setdefault(stem, set()).add(os.path.join(root, name))
    return found


def dependencies(found):
    graph = {}
    for stem, files in found.items():
        edges = set()
        for path in files:
            with open(path, encoding="utf-8", errors="replace") as source:
                for included in INCLUDE.findall(source.read()):
                    other = os.path.splitext(os.path.basename(included))[0]
                    if other != stem and other in found:
                        edges.add(other)
        graph[stem] = edges
    return graph


def cycles(graph):
    """The strongly connected components of more than one component (Tarjan), each as a
    cycle through its members."""
    index, low, stack, on_stack, result = {}, {}, [], set(), []

    def visit(node):
        index[node] = low[node] = len(index)
        stack.append(node)
        on_stack.add(node)
        for other in sorted(graph[node]):
            if other not in index:
                visit(other)
                low[node] = min(low[node], low[other])
            elif other in on_stack:
                low[node] = min(low[node], index[other])
        if low[node] == index[node]:
            members = []
            while True:
                member = stack.pop()
                on_stack.discard(member)
                members.append(member)
                if member == node:
                    break
            if len(members) > 1:
                result.append((cycle_through(graph, set(members)), sorted(members)))

    for node in sorted(graph):
        if node not in index:
            visit(node)
    return result


def cycle_through(graph, members):
    """One cycle inside the component, from its first member back to it (breadth first)."""
    start = min(members)
    paths = {start: [start]}
    queue = [start]
    while queue:
        node = queue.pop(0)
        for other in sorted(graph[node] & members):
            if other == start:
                return paths[node] + [start]
            if other not in paths:
                paths[other] = paths[node] + [other]
                queue.append(other)
    return sorted(members)


def main():
    sys.setrecursionlimit(10000)
    folder = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "..", "..", "Module")
    graph = dependencies(components(folder))
    found = cycles(graph)
    for cycle, members in found:
        print("cycle: " + " -> ".join(cycle))
        print("  all of these depend on each other: " + ", ".join(members))
    print("%d components, %d include cycles" % (len(graph), len(found)))
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
