#!/usr/bin/env python3
"""mutate.py --wash WASH --examples DIR [--count N] [--seed S] [--jobs J]:
the hostile mutation corpus. Makes N seeded mechanical mutants of the
examples (delete, duplicate or swap lines and tokens, truncate, random
bytes), runs the translator on each with a time limit, and asserts for every
run: no signal or crash report, no timeout, every error carries
file:line:col, the exit status is non-zero exactly when an error was
printed, nothing on stdout after an error, and no output folder after an
error (every fourth mutant is translated into a real folder; the others use
--dump-model). Prints a summary and each problem; exits 1 if there is one.

With --clang, the standard headers the wash API includes are precompiled
once and every run gets -include-pch: parsing them is most of a run's time,
and the mutants are about the simulation's own text, not the library's.
"""
import argparse
import glob
import os
import random
import re
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor

TOKEN = re.compile(rb"\w+|\S")
# A diagnostic line: "file:line:col: error:" (or "fatal error:").
LOCATED = re.compile(rb"^[^\s|][^|]*:\d+:\d+: (fatal )?error: ")
# clang's summary after 20 errors, which carried their places.
SUMMARY = b"fatal error: too many errors emitted, stopping now"
CRASH = (b"Stack dump", b"PLEASE submit a bug report", b"Segmentation fault")


def mutate(text, rng):
    """One mechanical mutation of text (bytes); returns (kind, mutant)."""
    lines = text.split(b"\n")
    tokens = [m.span() for m in TOKEN.finditer(text)]
    kind = rng.choice(["delete-line", "duplicate-line", "swap-lines", "delete-token",
                       "duplicate-token", "swap-tokens", "truncate", "random-bytes"])
    if kind == "delete-line":
        del lines[rng.randrange(len(lines))]
    elif kind == "duplicate-line":
        i = rng.randrange(len(lines))
        lines.insert(i, lines[i])
    elif kind == "swap-lines":
        i, j = rng.randrange(len(lines)), rng.randrange(len(lines))
        lines[i], lines[j] = lines[j], lines[i]
    elif kind in ("delete-token", "duplicate-token", "swap-tokens"):
        (b, e) = tokens[rng.randrange(len(tokens))]
        if kind == "delete-token":
            return kind, text[:b] + text[e:]
        if kind == "duplicate-token":
            return kind, text[:e] + b" " + text[b:e] + text[e:]
        (b2, e2) = tokens[rng.randrange(len(tokens))]
        if b2 < b:
            (b, e), (b2, e2) = (b2, e2), (b, e)
        if b2 < e:
            return kind, text
        return kind, text[:b] + text[b2:e2] + text[e:b2] + text[b:e] + text[e2:]
    elif kind == "truncate":
        return kind, text[:rng.randrange(len(text))]
    else:
        at = rng.randrange(len(text))
        noise = bytes(rng.randrange(256) for _ in range(rng.randrange(1, 16)))
        return kind, text[:at] + noise + text[at + rng.randrange(0, 16):]
    return kind, b"\n".join(lines)


def precompile(clang, api_dir, work):
    """A PCH of the standard headers the API headers include, or None (with
    the reason printed) if clang cannot build one wash can use."""
    headers = set()
    for header in glob.glob(os.path.join(api_dir, "wash", "*.hpp")):
        headers.update(re.findall(r"^#include <([a-z_]+)>", open(header).read(), re.M))
    source = os.path.join(work, "std.hpp")
    with open(source, "w") as f:
        f.writelines("#include <%s>\n" % h for h in sorted(headers))
    pch = source + ".pch"
    resource = subprocess.run([clang, "-print-resource-dir"], capture_output=True, text=True)
    build = subprocess.run([clang, "-x", "c++-header", "-std=c++20",
                            "-resource-dir=" + resource.stdout.strip(), source, "-o", pch],
                           capture_output=True, text=True)
    if build.returncode != 0:
        print("no precompiled header (runs parse every header):", build.stderr[:500],
              file=sys.stderr)
        return None
    return pch


def check(job):
    """Runs wash on one mutant; returns a list of problems (strings)."""
    wash, path, out, timeout, pch = job
    cmd = [wash, "--backend=serial", "-o", out, path] if out else [wash, "--dump-model", path]
    if pch:
        cmd += ["--", "-include-pch", pch]
    try:
        p = subprocess.run(cmd, capture_output=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return ["timeout after %d s" % timeout]
    problems = []
    if p.returncode < 0:
        problems.append("killed by signal %d" % -p.returncode)
    if any(c in p.stderr for c in CRASH):
        problems.append("crash report on stderr")
    errors = [l for l in p.stderr.split(b"\n") if b"error:" in l and not l[:1].isspace()
              and b"|" not in l[:8]]
    unlocated = [l for l in errors if not LOCATED.match(l)
                 and not (l.startswith(SUMMARY) and any(LOCATED.match(e) for e in errors))]
    if unlocated:
        problems.append("error without file:line:col: %r" % unlocated[0][:200])
    if bool(errors) != (p.returncode != 0):
        problems.append("exit status %d with %d errors" % (p.returncode, len(errors)))
    if p.returncode != 0 and p.stdout:
        problems.append("stdout written although it failed")
    if out and p.returncode != 0 and os.path.exists(out):
        problems.append("output folder left after an error")
    return problems


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--wash", required=True)
    ap.add_argument("--examples", required=True, help="folder of example folders")
    ap.add_argument("--count", type=int, default=504)
    ap.add_argument("--seed", type=int, default=16)
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 2)
    ap.add_argument("--timeout", type=int, default=60)
    ap.add_argument("--keep", help="folder to keep the mutants in")
    ap.add_argument("--clang", help="clang++ of wash's LLVM, to precompile the std headers")
    args = ap.parse_args()

    sources = sorted(glob.glob(os.path.join(args.examples, "*", "*.cpp")))
    rng = random.Random(args.seed)
    work = args.keep or tempfile.mkdtemp(prefix="wash-mutants-")
    os.makedirs(work, exist_ok=True)
    api_dir = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..",
                           "runtime", "include")
    pch = precompile(args.clang, api_dir, work) if args.clang else None
    jobs, kinds = [], []
    for i in range(args.count):
        src = sources[i % len(sources)]
        kind, text = mutate(open(src, "rb").read(), rng)
        folder = os.path.join(work, "%04d" % i)
        os.makedirs(folder, exist_ok=True)
        path = os.path.join(folder, os.path.basename(src))
        with open(path, "wb") as f:
            f.write(text)
        out = os.path.join(folder, "out") if i % 4 == 0 else None
        jobs.append((args.wash, path, out, args.timeout, pch))
        kinds.append(kind)
    with ThreadPoolExecutor(args.jobs) as pool:
        results = list(pool.map(check, jobs))
    failed = 0
    for (wash, path, out, _, _), kind, problems in zip(jobs, kinds, results):
        for problem in problems:
            print("PROBLEM %s (%s%s): %s" % (path, kind, ", -o" if out else "", problem))
        failed += bool(problems)
    print("%d mutants of %d examples (seed %d): %d with problems" %
          (len(jobs), len(sources), args.seed, failed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
