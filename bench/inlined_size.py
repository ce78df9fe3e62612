#!/usr/bin/env python3
"""How much code lavapipe compiles for a scene's tracer (a measuring tool, not a test).

lavapipe inlines every function call before its NIR passes, so a pipeline's creation costs about
as much as the module with every call inlined: each call site of a function is one more copy of
its body (docs/performance.md, "fewer copies of the shapes' code"). This renders SCENE at 1x1
into a fresh SPIR-V cache, takes the largest specialised tracer module from it and prints its
instruction count, the count with every call inlined, and the functions that weigh most inlined
(own size x copies). With --callers NAME, the call chains that copy the functions whose names
begin with NAME.

    bench/inlined_size.py scenes/cutaway.toml
    bench/inlined_size.py scenes/cutaway.toml --top 10 --callers leaf_hit
    bench/inlined_size.py --lancer /tmp/lancer-old scenes/chess.toml

Needs spirv-dis (Debian's spirv-tools, which ./setup.sh installs).
"""
import argparse
import collections
import pathlib
import re
import struct
import subprocess
import sys
import tempfile

SPIRV_MAGIC = struct.pack("<I", 0x07230203)


def tracer_module(lancer, scene, cache):
    """The largest tracer module lancer specialises for the scene (a cache entry, header stripped)."""
    subprocess.run([lancer, "render", scene, "--width", "1", "--height", "1", "-q", "-o", f"{cache}/one.png"],
                   check=True, env={"LANCER_CACHE_DIR": cache, "PATH": "/usr/bin:/bin"})
    entries = sorted(pathlib.Path(cache).glob("tracer-*.spv"), key=lambda p: p.stat().st_size)
    if not entries:
        sys.exit("no specialised tracer in the cache: is LANCER_CACHE_DISABLE set?")
    data = entries[-1].read_bytes()
    module = pathlib.Path(cache) / "module.spv"
    module.write_bytes(data[data.find(SPIRV_MAGIC):])
    return module


def call_graph(module):
    """Each function's own instruction count, its calls (one entry per call site) and names."""
    text = subprocess.run(["spirv-dis", "--raw-id", str(module)], capture_output=True, text=True, check=True).stdout
    names, size, calls = {}, {}, collections.defaultdict(list)
    current = None
    for line in text.splitlines():
        if m := re.match(r'\s*(%\d+) = OpFunction ', line):
            current = m.group(1)
            size[current] = 0
        elif current and "OpFunctionEnd" in line:
            current = None
        elif current:
            size[current] += 1
            if m := re.search(r"OpFunctionCall %\d+ (%\d+)", line):
                calls[current].append(m.group(1))
        elif m := re.match(r'\s*OpName (%\d+) "([^"]*)"', line):
            names[m.group(1)] = m.group(2)
    return names, size, calls


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("scene")
    parser.add_argument("--lancer", default="build/lancer")
    parser.add_argument("--top", type=int, default=15)
    parser.add_argument("--callers", help="show the call chains to functions whose names begin with this")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as cache:
        names, size, calls = call_graph(tracer_module(args.lancer, args.scene, cache))
    name = lambda f: names.get(f, f).split("(")[0]

    inlined = {}

    def inlined_size(f):
        if f not in inlined:
            inlined[f] = size.get(f, 0) + sum(inlined_size(c) for c in calls[f])
        return inlined[f]

    main_id = next(f for f in size if names.get(f) == "main")
    copies = collections.Counter()

    def count(f, n):
        copies[f] += n
        for c in calls[f]:
            count(c, n)

    count(main_id, 1)
    print(f"{args.scene}: {sum(size.values())} instructions, {inlined_size(main_id)} with every call inlined")
    print(f"{'inlined':>8}  {'own':>6}  {'copies':>6}  function")
    for f in sorted(copies, key=lambda f: -size[f] * copies[f])[:args.top]:
        print(f"{size[f] * copies[f]:8d}  {size[f]:6d}  {copies[f]:6d}  {name(f)}")
    if args.callers:
        callers = collections.defaultdict(list)
        for f, cs in calls.items():
            for c in cs:
                callers[c].append(f)

        def chains(f, depth):
            for c in sorted(set(callers[f]), key=name):
                print(f"{'  ' * depth}{name(c)} x{callers[f].count(c)} ({copies[c]} copies)")
                chains(c, depth + 1)

        for f in (f for f in size if names.get(f, "").startswith(args.callers)):
            print(f"{name(f)}: {inlined_size(f)} inlined, {copies[f]} copies, called from")
            chains(f, 1)


if __name__ == "__main__":
    main()
