#!/usr/bin/env python3
"""The Khronos glTF-Validator's test corpus through Wavefront's loader (issue 45).

    test_gltf_validator_corpus.py CORPUS_DIR WAVEFRONT [--jobs N]

CORPUS_DIR holds the validator's test/ folder (third-party data, unmodified): every .gltf and
.glb has NAME.report.json beside it, and issues.numErrors == 0 there means the file is valid.
Each file is rendered in its own process, `WAVEFRONT render FILE` at 8x8 and 1 spp (the whole
corpus takes about 15 s on 2 cores with lavapipe). Fails when a valid file is refused (exit 2) other than those NETWORK_URIS lists, when any file
(valid or not) crashes (an exit code other than 0 and 2, or a signal) or hangs (runs past
HANG_SECONDS, far beyond any load's time: only a hang reaches it), or when the corpus is
missing. Prints the counts.
"""
import argparse
import concurrent.futures
import json
import os
import subprocess
import sys
import tempfile

# Valid files Wavefront refuses on purpose, with the reason: files are read from the scene's
# folder only, never from the network (docs/gltf.md).
NETWORK_URIS = {
    "base/data/buffer/non_relative_uri.gltf":
        "its buffer's uri is http://example.com/buffer.bin; network URIs are refused",
}
HANG_SECONDS = 300


def corpus_files(root):
    out = []
    for folder, _, names in os.walk(root):
        for name in names:
            if name.endswith((".gltf", ".glb")):
                out.append(os.path.relpath(os.path.join(folder, name), root))
    return sorted(out)


def run_one(args, root, relative, scratch):
    path = os.path.join(root, relative)
    output = os.path.join(scratch, relative.replace("/", "_") + ".exr")
    command = [args.wavefront, "render", path, "--width", "8", "--height", "8", "--spp", "1",
               "-o", output, "--quiet"]
    try:
        done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                              timeout=HANG_SECONDS, text=True, errors="replace")
    except subprocess.TimeoutExpired:
        return relative, "hang", f"still running after {HANG_SECONDS} s"
    text = (done.stdout + done.stderr).strip().splitlines()
    last = text[-1] if text else ""
    if done.returncode == 0:
        return relative, "rendered", last
    if done.returncode == 2:
        refusal = [line for line in text if "refused" in line or line.startswith("wavefront:")]
        return relative, "refused", (refusal or text or [""])[-1]
    how = (f"signal {-done.returncode}" if done.returncode < 0
           else f"exit code {done.returncode}")
    return relative, "crash", f"{how}: {last}"


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("corpus")
    parser.add_argument("wavefront")
    parser.add_argument("--jobs", type=int, default=min(4, os.cpu_count() or 1))
    args = parser.parse_args()

    root = args.corpus
    if not os.path.isdir(root) or not corpus_files(root):
        print(f"FAIL: the glTF-Validator corpus is missing: no .gltf or .glb under {root} "
              "(CI keeps KhronosGroup/glTF-Validator's test/ folder at "
              "../shared/corpus/gltf-validator from the project root)")
        return 1
    files = corpus_files(root)
    valid = {}
    for relative in files:
        report = os.path.join(root, relative + ".report.json")
        try:
            with open(report, encoding="utf-8") as f:
                valid[relative] = json.load(f)["issues"]["numErrors"] == 0
        except (OSError, ValueError, KeyError) as e:
            print(f"FAIL: {relative}: its report {report} cannot be read ({e})")
            return 1

    with tempfile.TemporaryDirectory() as scratch, \
            concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        results = list(pool.map(lambda r: run_one(args, root, r, scratch), files))

    failures = []
    counts = {"rendered": [0, 0], "refused": [0, 0], "crash": [0, 0], "hang": [0, 0]}
    for relative, outcome, detail in results:
        counts[outcome][0 if valid[relative] else 1] += 1
        if outcome in ("crash", "hang"):
            failures.append(f"{outcome}: {relative}: {detail}")
        elif valid[relative] and outcome == "refused" and relative not in NETWORK_URIS:
            failures.append(f"valid but refused: {relative}: {detail}")
        elif relative in NETWORK_URIS and outcome != "refused":
            failures.append(f"listed as a network URI but {outcome}: {relative}: {detail}")
    for relative, reason in NETWORK_URIS.items():
        if relative not in valid:
            failures.append(f"listed as a network URI but not in the corpus: {relative}")
        elif not valid[relative]:
            failures.append(f"listed as a network URI but invalid by its report: {relative}")

    n_valid = sum(valid.values())
    print(f"{len(files)} files: {n_valid} valid by their reports, {len(files) - n_valid} invalid "
          "(rendered at 8x8, 1 spp, one process each)")
    for outcome, (v, i) in counts.items():
        print(f"  {outcome:8s} {v:4d} valid  {i:4d} invalid")
    for relative, reason in NETWORK_URIS.items():
        print(f"  refused on purpose: {relative}: {reason}")
    for line in failures:
        print("FAIL " + line)
    print("ok" if not failures else f"{len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
