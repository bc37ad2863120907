#!/usr/bin/env python3
"""Where lavapipe spends a `wavefront bench` run: samples the JIT'ed shader code with perf,
copies that code out of the running process with gdb and disassembles it, then reports the
share of samples in each compiled shader, in each of its loops, and writes every shader's
disassembly with a sample count on each instruction. Needs perf, gdb and objdump (Debian:
linux-perf, gdb, binutils); standard library otherwise.

    python3 bench/profile_lavapipe.py SCENE.gltf [--wavefront build/wavefront] [--width 256]
        [--seconds 8] [--out out/profile] [-- extra bench options]

llvmpipe keeps each shader's machine code in an anonymous executable mapping and names none
of it, so the report lists shaders by address and size; match them to passes by their share
against the per-pass times that `wavefront bench` prints (bench.txt in the output folder).
Samples land on the instruction after one that stalls (skid): a count behind a load is the
load's.
"""
import argparse
import collections
import os
import re
import shutil
import signal
import subprocess
import sys
import time

INSTRUCTION = re.compile(r"\s*([0-9a-f]+):\s+((?:[0-9a-f]{2} )+)\s*(.*)")
BACKWARD_JUMP = re.compile(r"(j\w+)\s+0x([0-9a-f]+)")


def anonymous_code(pid):
    """(start, end) of each anonymous executable mapping: llvmpipe's JIT'ed code."""
    ranges = []
    with open("/proc/%d/maps" % pid) as maps:
        for line in maps:
            fields = line.split()
            if len(fields) == 5 and "x" in fields[1] and fields[4] == "0":
                start, end = (int(v, 16) for v in fields[0].split("-"))
                ranges.append((start, end))
    return ranges


def dump_code(pid, ranges, folder):
    commands = []
    for start, end in ranges:
        commands += ["-ex", "dump memory %s/code_%x.bin 0x%x 0x%x" % (folder, start, start, end)]
    subprocess.run(["gdb", "-p", str(pid), "-batch"] + commands, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL, check=False)


def disassemble(path, start):
    text = subprocess.run(["objdump", "-D", "-b", "binary", "-m", "i386:x86-64",
                           "--adjust-vma=0x%x" % start, path], capture_output=True, text=True,
                          check=True).stdout
    out = []
    for line in text.splitlines():
        m = INSTRUCTION.match(line)
        if m and m.group(3):
            out.append((int(m.group(1), 16), m.group(3).strip()))
    return out


def loops(instructions, counts, total, floor):
    """Every backward jump's range with its share of the samples, largest first."""
    found = []
    for address, text in instructions:
        m = BACKWARD_JUMP.match(text)
        if not m or int(m.group(2), 16) >= address:
            continue
        target = int(m.group(2), 16)
        body = [a for a, _ in instructions if target <= a <= address]
        share = sum(counts.get(a, 0) for a in body) / total
        if share >= floor:
            found.append((share, target, address, len(body)))
    return sorted(found, reverse=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("scene")
    parser.add_argument("--wavefront", default="build/wavefront")
    parser.add_argument("--width", type=int, default=256)
    parser.add_argument("--seconds", type=float, default=8.0, help="how long perf samples")
    parser.add_argument("--out", default="out/profile")
    parser.add_argument("bench_options", nargs="*", help="after --: passed to wavefront bench")
    args = parser.parse_args()
    missing = [tool for tool in ("perf", "gdb", "objdump") if shutil.which(tool) is None]
    if missing:
        sys.exit("profile_lavapipe.py: needs %s on PATH" % ", ".join(missing))
    os.makedirs(args.out, exist_ok=True)

    def bench_command(frames):
        return [args.wavefront, "bench", args.scene, "--width", str(args.width), "--frames",
                str(frames), "--warmup", "1", "-q"] + args.bench_options

    # First the per-pass times to match the shaders against, then a run that outlasts
    # compilation and the sampling window.
    with open(os.path.join(args.out, "bench.txt"), "w") as bench:
        first = subprocess.run(bench_command(4), stdout=bench, stderr=subprocess.STDOUT,
                               check=False)
    if first.returncode != 0:
        with open(os.path.join(args.out, "bench.txt")) as bench:
            lines = bench.read().strip().splitlines()
        print("profile_lavapipe.py: wavefront bench failed: %s" % (lines[-1] if lines else
              "exit %d" % first.returncode), file=sys.stderr)
        sys.exit(first.returncode)
    process = subprocess.Popen(bench_command(100000), stdout=subprocess.DEVNULL,
                               stderr=subprocess.DEVNULL)
    try:
        time.sleep(4.0)  # shaders compiled, frames running
        if process.poll() is not None:
            sys.exit("profile_lavapipe.py: wavefront bench ended early; see %s/bench.txt" % args.out)
        data = os.path.join(args.out, "perf.data")
        subprocess.run(["perf", "record", "-q", "-e", "cpu-clock", "-F", "2000", "-p",
                        str(process.pid), "-o", data, "--", "sleep", str(args.seconds)],
                       check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        ranges = anonymous_code(process.pid)
        dump_code(process.pid, ranges, args.out)
    finally:
        process.send_signal(signal.SIGINT)
        try:
            process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            process.kill()
    script = subprocess.run(["perf", "script", "-i", data, "-F", "ip"], capture_output=True,
                            text=True, check=True).stdout
    samples = [int(v, 16) for v in script.split()]
    if not samples:
        sys.exit("profile_lavapipe.py: perf recorded no samples")
    by_shader = collections.Counter()
    per_address = collections.Counter(samples)
    for ip in samples:
        by_shader[next((r for r in ranges if r[0] <= ip < r[1]), None)] += 1

    print("%d samples over %.0f s; %.1f%% outside the JIT'ed code (driver, kernel, host)" %
          (len(samples), args.seconds, 100.0 * by_shader[None] / len(samples)))
    for shader, count in by_shader.most_common():
        if shader is None or count < 0.01 * len(samples):
            continue
        start, end = shader
        path = os.path.join(args.out, "code_%x.bin" % start)
        if not os.path.exists(path):
            continue
        instructions = disassemble(path, start)
        print("\nshader at 0x%x (%d bytes, %d instructions): %.1f%% of all samples" %
              (start, end - start, len(instructions), 100.0 * count / len(samples)))
        for share, target, jump, size in loops(instructions, per_address, count, 0.02):
            print("  loop +0x%x..+0x%x, %d instructions: %.1f%% of this shader" %
                  (target - start, jump - start, size, 100.0 * share))
        with open(os.path.join(args.out, "code_%x.s" % start), "w") as listing:
            for address, text in instructions:
                listing.write("%6d  +%05x  %s\n" % (per_address.get(address, 0), address - start,
                                                    text))
    print("\nannotated listings (samples, offset, instruction): %s/code_*.s" % args.out)
    print("per-pass times of the same scene: %s/bench.txt" % args.out)


if __name__ == "__main__":
    main()
