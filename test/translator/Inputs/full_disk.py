#!/usr/bin/env python3
"""full_disk.py WASH WORKDIR: translates onto a nearly full 64 KB tmpfs and
prints what happened, for FileCheck. Needs root (it mounts); the mount is
always removed. Checks: a write that runs out of space fails with "No space
left on device" and a non-zero exit, within a time limit; it leaves no new
project behind, and a previous project untouched (not a mix of old and
new files)."""
import os
import shutil
import subprocess
import sys

wash, work = sys.argv[1], sys.argv[2]
shutil.rmtree(work, ignore_errors=True)
mnt = os.path.join(work, "mnt")
os.makedirs(mnt)
KERNEL = """#include <wash/wash.hpp>
void Heat(wash::Particle& p) { p.set_density(p.get_density() * %s); }
int main() {
  wash::set_influence_radius(0.1);
  wash::add_update_kernel(&Heat);
  wash::set_max_iterations(1);
  wash::start();
}
"""
old_src, new_src = os.path.join(work, "old", "sim.cpp"), os.path.join(work, "new", "sim.cpp")
for src, factor in ((old_src, "2.0"), (new_src, "3.0 + p.get_mass()")):
    os.makedirs(os.path.dirname(src))
    with open(src, "w") as f:
        f.write(KERNEL % factor)


def translate(src, out):
    try:
        p = subprocess.run([wash, "--backend=serial", "-o", out, src], capture_output=True,
                           text=True, timeout=60)
    except subprocess.TimeoutExpired:
        print("TIMEOUT: wash -o %s" % out)
        return
    errors = [l for l in p.stderr.splitlines() if "error:" in l]
    print("exit %d: %s" % (p.returncode, errors[0] if errors else "no error"))


def snapshot(d):
    return {n: open(os.path.join(d, n), "rb").read() for n in sorted(os.listdir(d))}


subprocess.run(["mount", "-t", "tmpfs", "-o", "size=64k", "tmpfs", mnt], check=True)
try:
    proj = os.path.join(mnt, "proj")
    print("previous project:")
    translate(old_src, proj)
    before = snapshot(proj)
    # Leave a few KB: the staging folder and the first files fit, not all.
    free = os.statvfs(mnt).f_bavail * os.statvfs(mnt).f_frsize
    with open(os.path.join(mnt, "fill"), "wb") as f:
        f.write(b"\0" * max(0, free - 4096))
    print("over the previous project:")
    translate(new_src, proj)
    print("previous project %s" % ("unchanged" if snapshot(proj) == before else "CHANGED"))
    print("into a new folder:")
    translate(new_src, os.path.join(mnt, "fresh"))
    print("left on the disk: %s" % " ".join(sorted(os.listdir(mnt))))
finally:
    subprocess.run(["umount", mnt], check=True)
