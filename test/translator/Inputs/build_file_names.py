#!/usr/bin/env python3
"""build_file_names.py [-GGENERATOR] WASH CXX WORKDIR NAME...: for each NAME,
copies a trivial simulation to WORKDIR/NAME.cpp, translates it (serial
backend) and configures and builds the generated CMake project with CXX and
GENERATOR (default Ninja). Prints one line a name: "NAME: built", or the step
that failed and its last output lines. In NAME, \\t and \\n stand for a tab
and a line break."""
import os
import shutil
import subprocess
import sys

args = sys.argv[1:]
generator = "Ninja"
if args[0].startswith("-G"):
    generator = args.pop(0)[2:]
wash, cxx, work, names = args[0], args[1], args[2], args[3:]
SIM = """#include <wash/wash.hpp>
void Heat(wash::Particle& p) { p.set_density(p.get_density() * 2.0); }
void Init() { wash::create_particle(1.0, 1.0, 0.1, wash::Vec2D{0.0, 0.0}, wash::Vec2D{}); }
int main() {
  wash::set_influence_radius(0.1);
  wash::add_init_kernel(&Init);
  wash::add_update_kernel(&Heat);
  wash::set_max_iterations(1);
  wash::start();
}
"""
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
for i, shown in enumerate(names):
    name = shown.replace("\\t", "\t").replace("\\n", "\n")
    src = os.path.join(work, name + ".cpp")
    # CMake cannot build in a folder whose own path has a ';'.
    proj = os.path.join(work, "project-%d" % i)
    with open(src, "w") as f:
        f.write(SIM)
    steps = [("translate", [wash, "--backend=serial", "-o", proj, src]),
             ("configure", ["cmake", "-S", proj, "-B", os.path.join(proj, "build"), "-G", generator,
                            "-DCMAKE_CXX_COMPILER=" + cxx, "-DCMAKE_BUILD_TYPE=Release"]),
             ("build", ["cmake", "--build", os.path.join(proj, "build")])]
    for step, cmd in steps:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
        if p.returncode != 0:
            tail = (p.stdout + p.stderr).strip().splitlines()[-3:]
            print("%s: %s failed: %s" % (shown, step, " | ".join(tail)))
            break
    else:
        print("%s: built" % shown)
