#!/usr/bin/env python3
"""expect_exit.py STATUS CMD...: runs CMD, fails unless it exits with STATUS
without crashing; after a failure it must also print nothing on stdout (no
partial output). Prints CMD's stderr, then its stdout, for FileCheck.

`not` alone cannot say this: it accepts any non-zero status."""
import subprocess
import sys

want = int(sys.argv[1])
proc = subprocess.run(sys.argv[2:], capture_output=True, timeout=60)
out = proc.stdout.decode("utf-8", "replace")
err = proc.stderr.decode("utf-8", "replace")
sys.stdout.write(err + out)
problems = []
if proc.returncode != want:
    problems.append("exit status %d, expected %d" % (proc.returncode, want))
for crash in ("Stack dump", "PLEASE submit a bug report", "Segmentation fault"):
    if crash in err or crash in out:
        problems.append("crashed: %r in output" % crash)
if want != 0 and out:
    problems.append("wrote to stdout although it failed")
for p in problems:
    sys.stderr.write("expect_exit.py: %s\n" % p)
sys.exit(1 if problems else 0)
