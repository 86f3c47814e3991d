#!/usr/bin/env python3
"""build_file_names.py WASH CXX WORKDIR NAME...: for each NAME, copies a
trivial simulation to WORKDIR/NAME.cpp, translates it (serial backend) and
configures and builds the generated CMake project with CXX. Prints one line
a name: "NAME: built", or the step that failed and its last output lines."""
import os
import shutil
import subprocess
import sys

wash, cxx, work, names = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
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
for i, name in enumerate(names):
    src = os.path.join(work, name + ".cpp")
    # CMake cannot build in a folder whose own path has a ';'.
    proj = os.path.join(work, "project-%d" % i)
    with open(src, "w") as f:
        f.write(SIM)
    steps = [("translate", [wash, "--backend=serial", "-o", proj, src]),
             ("configure", ["cmake", "-S", proj, "-B", os.path.join(proj, "build"), "-G", "Ninja",
                            "-DCMAKE_CXX_COMPILER=" + cxx, "-DCMAKE_BUILD_TYPE=Release"]),
             ("build", ["cmake", "--build", os.path.join(proj, "build")])]
    for step, cmd in steps:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
        if p.returncode != 0:
            tail = (p.stdout + p.stderr).strip().splitlines()[-3:]
            print("%s: %s failed: %s" % (name, step, " | ".join(tail)))
            break
    else:
        print("%s: built" % name)
