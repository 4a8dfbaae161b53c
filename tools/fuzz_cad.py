#!/usr/bin/env python3
"""Mutation fuzzing of the CAD and mesh readers through the command users run.

The STEP/IGES reader runs OpenCASCADE in a helper process (the crash probe) and meshes go through
assimp: a libFuzzer target in-process would only fuzz the probe's pipe. So this fuzzer mutates real
files (the samples and the third-party CAD under tests/data) and runs `cablefit relax` on each, and
checks the contract of every run, whatever the input:
  - it ends within what cablefit promises for the file's size (run_limit): a hang is a finding;
  - exit 0, 1 or 2, never a signal or an abort;
  - a failure names the input file on stderr;
  - the input is unchanged, nothing is written outside --out, no temp file is left in TMPDIR;
  - exit 0 leaves the input's JSON in --out.
Findings are kept in ARTIFACTS with the command that reproduces them; exit 1 if any.

Usage: tools/fuzz_cad.py CABLEFIT SECONDS ARTIFACTS [SEED]
(no SEED: one from the clock, to explore; CI passes a fixed one, so that its runs are reproducible)
"""
import hashlib
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SEEDS = [
    "samples/harness/legacy_harness.step",
    "samples/harness/legacy_harness.igs",
    "samples/harness/bent_tubes.stl",
    "samples/harness/branched_tubes.stl",
    "tests/data/flat/flat_cables.step",
    "tests/data/realcad/cables_harness_example_routes.step",
    "tests/data/realcad/occt_bug23171_tube_surf.igs",
]
NUMBERS = [b"nan", b"NaN", b"inf", b"-inf", b"1e308", b"-1e308", b"1.E+308", b"0.", b"-0.",
           b"1e-320", b"99999999999999999999999", b"", b"1.2.3", b"0x10"]
NUMBER = re.compile(rb"-?\d+\.\d*(?:[eE][-+]?\d+)?")
REFERENCE = re.compile(rb"#\d+")
TIMEOUT = 20  # [s] cablefit's --timeout: each cable (or group solved together)


def run_limit(size):
    """[s] The longest one run may take before it counts as a hang: what cablefit promises for
    a file of `size` bytes (a STEP/IGES probe ends at 30 s + 30 s per MB, and the in-process read
    after a probe takes about as long), plus a minute for relaxing at --timeout and writing."""
    probe = 30 + 30 * size / 1e6
    return 2 * probe + 60


def mutate(data, rng, other):
    """One to four mutations of `data` (bytes)."""
    for _ in range(rng.randint(1, 4)):
        kind = rng.randrange(9)
        if not data:
            return data
        if kind == 0:  # truncated file
            data = data[:rng.randrange(len(data))]
        elif kind == 1:  # flipped bytes
            b = bytearray(data)
            for _ in range(rng.randint(1, 8)):
                b[rng.randrange(len(b))] = rng.randrange(256)
            data = bytes(b)
        elif kind in (2, 3):  # a number replaced by a hostile one
            found = list(NUMBER.finditer(data[:200000]))
            if found:
                m = rng.choice(found)
                data = data[:m.start()] + rng.choice(NUMBERS) + data[m.end():]
        elif kind == 4:  # a dangling or self reference
            found = list(REFERENCE.finditer(data[:200000]))
            if found:
                m = rng.choice(found)
                data = data[:m.start()] + rng.choice([b"#999999999", b"#1", b"#0", b"#"]) + data[m.end():]
        elif kind == 5:  # a line deleted or repeated
            lines = data.split(b"\n")
            i = rng.randrange(len(lines))
            if rng.random() < 0.5:
                del lines[i]
            else:
                lines.insert(i, lines[i] * rng.randint(1, 3))
            data = b"\n".join(lines)
        elif kind == 6:  # a chunk of another input spliced in
            a = rng.randrange(len(other))
            data_at = rng.randrange(len(data))
            data = data[:data_at] + other[a:a + rng.randint(1, 4096)] + data[data_at:]
        elif kind == 7 and len(data) > 84:  # binary STL: a triangle count that lies
            count = rng.choice([0, 1, 0xFFFFFFFF, 0x7FFFFFFF, (len(data) - 84) // 50 + 1])
            data = data[:80] + count.to_bytes(4, "little") + data[84:]
        else:  # a block of the file repeated
            a = rng.randrange(len(data))
            data = data[:a] + data[a:a + rng.randint(1, 2048)] * rng.randint(2, 50) + data[a:]
    return data


def digest(path):
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


def run_one(cablefit, source, data, workdir):
    """Runs relax on `data` (named like `source`); returns the broken promises (empty: fine)."""
    shutil.rmtree(workdir, ignore_errors=True)
    os.makedirs(os.path.join(workdir, "tmp"))
    name = os.path.basename(source)
    path = os.path.join(workdir, name)
    with open(path, "wb") as f:
        f.write(data)
    before = digest(path)
    env = dict(os.environ, TMPDIR=os.path.join(workdir, "tmp"))
    command = [cablefit, "relax", path, "--out", os.path.join(workdir, "out"), "--timeout",
               str(TIMEOUT), "--quiet", "--no-pictures"]
    broken = []
    limit = run_limit(len(data))
    try:
        p = subprocess.run(command, cwd=workdir, env=env, capture_output=True, timeout=limit)
    except subprocess.TimeoutExpired:
        return ["did not end within %d s" % limit], command
    err = p.stderr.decode("utf-8", "replace")
    if p.returncode < 0:
        broken.append("killed by signal %d" % -p.returncode)
    elif p.returncode not in (0, 1, 2):
        broken.append("exit %d" % p.returncode)
    if p.returncode in (1, 2) and name not in err:
        broken.append("the failure does not name the input: " + err.strip()[:300])
    if digest(path) != before:
        broken.append("the input was changed")
    extra = set(os.listdir(workdir)) - {name, "out", "tmp"}
    if extra:
        broken.append("wrote outside --out: " + ", ".join(sorted(extra)))
    left = os.listdir(os.path.join(workdir, "tmp"))
    if left:
        broken.append("left temp files: " + ", ".join(sorted(left)[:5]))
    stem = os.path.splitext(name)[0]
    if p.returncode == 0 and not any(f.endswith(".json") for f in os.listdir(os.path.join(workdir, "out"))
                                     if f.startswith(stem)):
        broken.append("exit 0 without %s's JSON" % name)
    if broken:
        broken.append("stderr: " + err.strip()[-400:])
    return broken, command


def main():
    if len(sys.argv) < 4:
        print(__doc__)
        return 2
    cablefit, seconds, artifacts = os.path.abspath(sys.argv[1]), float(sys.argv[2]), sys.argv[3]
    seed = int(sys.argv[4]) if len(sys.argv) > 4 else int(time.time())
    if "--no-pictures" not in subprocess.run([cablefit, "relax", "--help"], capture_output=True,
                                             text=True).stdout:
        raise SystemExit("fuzz_cad: %s relax has no --no-pictures" % cablefit)
    rng = random.Random(seed)
    seeds = [os.path.join(ROOT, s) for s in SEEDS if os.path.exists(os.path.join(ROOT, s))]
    blobs = {s: open(s, "rb").read() for s in seeds}
    os.makedirs(artifacts, exist_ok=True)
    work = tempfile.mkdtemp(prefix="cablefit-fuzz-cad-")
    runs = findings = 0
    end = time.monotonic() + seconds
    try:
        while time.monotonic() < end:
            source = rng.choice(seeds)
            data = mutate(blobs[source], rng, blobs[rng.choice(seeds)])
            broken, command = run_one(cablefit, source, data, os.path.join(work, "run"))
            runs += 1
            if broken:
                findings += 1
                kept = os.path.join(artifacts, "cad-%d-%d-%s" % (seed, runs, os.path.basename(source)))
                with open(kept, "wb") as f:
                    f.write(data)
                print("fuzz_cad: FINDING %s: %s" % (kept, "; ".join(broken)))
                print("  reproduce: %s" % " ".join(c if c != command[2] else kept for c in command))
    finally:
        shutil.rmtree(work, ignore_errors=True)
    print("fuzz_cad: seed %d, %d runs, %d findings" % (seed, runs, findings))
    return 1 if findings else 0


if __name__ == "__main__":
    sys.exit(main())
