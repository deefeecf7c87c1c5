#!/usr/bin/env python3
"""Where lavapipe's compiled kernel spends its instructions, instruction by instruction.

Renders SCENE under valgrind's callgrind (raytex_bench_frames: one frame that compiles the
kernel, then FRAMES more) with a fresh Mesa shader cache, takes the x86 object code llvmpipe
stored in that cache (an ELF object, zstd-compressed), disassembles it with objdump, and lines
each instruction up with how often it ran. Prints the instructions per pixel, how they split
between code run once per SIMD vector of 8 invocations and code run once per lane (lavapipe's
scalarised loads and stores, loops over the lanes), and the most frequent operations; writes
the annotated listing to LISTING.

It showed that storage-buffer loads in control flow become loops over the lanes (common.h,
BINDING_SPHERES) and what the noise's gradient vectors cost (noise.glsl, noiseGradientDot).

Needs valgrind, objdump (binutils) and zstd. One thread, so counts are exact; about a minute
at 320x240. Usage: bench/kernel_profile.py BUILD_DIR SCENE   (env: WIDTH, HEIGHT, FRAMES,
LISTING, default 320 240 2 kernel_profile.txt)
"""
import argparse
import collections
import os
import re
import subprocess
import sys
import tempfile

ZSTD_MAGIC = b"\x28\xb5\x2f\xfd"
HOT_SYMBOL = "cs_co_variant"  # the per-SIMD-vector body of llvmpipe's compute shader


def run_callgrind(args, cache_dir, out_file):
    env = dict(os.environ, LP_NUM_THREADS="1", MESA_SHADER_CACHE_DIR=cache_dir)
    env.setdefault("VK_ICD_FILENAMES", "/usr/share/vulkan/icd.d/lvp_icd.x86_64.json")
    env.pop("MESA_SHADER_CACHE_DISABLE", None)
    frames = os.path.join(args.build, "raytex_bench_frames")
    if not os.access(frames, os.X_OK):
        sys.exit(f"kernel_profile.py: no {frames} (build it first)")
    subprocess.run(["valgrind", "--tool=callgrind", "--smc-check=all", "--dump-instr=yes",
                    f"--callgrind-out-file={out_file}", frames, args.scene, str(args.width),
                    str(args.height), str(args.frames)],
                   env=env, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def parse_callgrind(path):
    """Per-address instruction counts of every function without a name (JIT code)."""
    names, counts = {}, collections.defaultdict(collections.Counter)
    current, addr, skip_next = None, 0, False
    for line in open(path):
        if line.startswith(("fn=", "cfn=")):
            m = re.match(r"c?fn=\((\d+)\)(?: (.*))?", line.rstrip("\n"))
            if m.group(2):
                names[m.group(1)] = m.group(2)
            if line.startswith("fn="):
                name = names.get(m.group(1), "")
                current = int(name, 16) if re.fullmatch(r"0x[0-9a-f]+", name) else None
            continue
        if current is None:
            continue
        if line.startswith("calls="):
            skip_next = True  # the next cost line is the callee's inclusive cost
            continue
        if not line or line[0] not in "0123456789+-*":
            continue
        parts = line.split()
        a = parts[0]
        if a.startswith("0x"):
            addr = int(a, 16)
        elif a[0] in "+-":
            delta = int(a[1:], 16) if a[1:].startswith("0x") else int(a[1:])
            addr += delta if a[0] == "+" else -delta
        if skip_next:
            skip_next = False
            continue
        if len(parts) > 2:  # positions: instr line
            counts[current][addr] += int(parts[2])
    return counts


def cached_object(cache_dir):
    """The largest llvmpipe object in the cache, decompressed: the trace kernel."""
    entries = [os.path.join(d, f) for d, _, fs in os.walk(cache_dir) for f in fs if f != "index"]
    if not entries:
        sys.exit("kernel_profile.py: Mesa's shader cache stayed empty (is MESA_SHADER_CACHE_DISABLE set?)")
    data = open(max(entries, key=os.path.getsize), "rb").read()
    start = data.find(ZSTD_MAGIC)
    if start < 0:
        sys.exit("kernel_profile.py: the cache entry holds no zstd frame")
    return subprocess.run(["zstd", "-q", "-d", "-c"], input=data[start:], stdout=subprocess.PIPE,
                          check=True).stdout


def disassemble(obj):
    with tempfile.NamedTemporaryFile(suffix=".o") as f:
        f.write(obj)
        f.flush()
        text = subprocess.run(["objdump", "-d", "--no-show-raw-insn", f.name], stdout=subprocess.PIPE,
                              check=True, text=True).stdout
    symbols, lines = {}, []
    for line in text.splitlines():
        m = re.match(r"([0-9a-f]+) <(.*)>:", line)
        if m:
            symbols[m.group(2)] = int(m.group(1), 16)
        m = re.match(r"\s*([0-9a-f]+):\s+(\S+)\s*(.*)", line)
        lines.append((int(m.group(1), 16), m.group(2), m.group(3)) if m else (None, line, ""))
    return symbols, lines


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0],
                                epilog="env: WIDTH, HEIGHT, FRAMES, LISTING (default 320 240 2 kernel_profile.txt)")
    p.add_argument("build")
    p.add_argument("scene")
    args = p.parse_args()
    try:
        args.width = int(os.environ.get("WIDTH", "320"))
        args.height = int(os.environ.get("HEIGHT", "240"))
        args.frames = int(os.environ.get("FRAMES", "2"))
    except ValueError as e:
        p.error(f"WIDTH, HEIGHT and FRAMES are integers ({e})")
    args.listing = os.environ.get("LISTING", "kernel_profile.txt")
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "callgrind.out")
        run_callgrind(args, os.path.join(tmp, "cache"), out)
        counts = parse_callgrind(out)
        symbols, lines = disassemble(cached_object(os.path.join(tmp, "cache")))
    if not counts or HOT_SYMBOL not in symbols:
        sys.exit("kernel_profile.py: found no JIT code or no " + HOT_SYMBOL)
    # The hottest JIT function is the kernel body; callgrind names it by its address.
    hot = max(counts, key=lambda f: sum(counts[f].values()))
    base = hot - symbols[HOT_SYMBOL]
    per_addr = {a - base: n for a, n in counts[hot].items()}
    pixels = args.width * args.height * (args.frames + 1)
    vectors = pixels // 8
    total = sum(per_addr.values())
    matched = sum(per_addr.get(a, 0) for a, _, _ in lines if a is not None)
    print(f"{args.scene} {args.width}x{args.height}: {total / pixels:.0f} instructions per pixel in the kernel")
    # Code run once per vector, in loops over the 8 lanes (x8) or in the shader's own loops.
    runs = collections.Counter()
    for n in per_addr.values():
        runs[round(n / vectors, 1)] += n
    print("  by executions per vector of 8 invocations (instructions per pixel): " +
          ", ".join(f"x{k:g} {n / pixels:.0f}" for k, n in runs.most_common(6)))
    if matched != total:
        print(f"  warning: {total - matched} counted instructions are not in the cached object")
    ops = collections.Counter()
    for a, op, _ in lines:
        if a is not None:
            ops[op] += per_addr.get(a, 0)
    print("  most frequent operations (per pixel): " +
          ", ".join(f"{op} {n / pixels:.0f}" for op, n in ops.most_common(10)))
    with open(args.listing, "w") as f:
        f.write(f"# {args.scene} {args.width}x{args.height}, {args.frames + 1} frames: executions per "
                f"instruction ({vectors} = once per vector of 8 invocations)\n")
        for a, op, rest in lines:
            f.write(f"{per_addr.get(a, 0):10d}  {a:6x}:  {op} {rest}\n" if a is not None else op + "\n")
    print(f"  annotated listing: {args.listing}")


if __name__ == "__main__":
    main()
