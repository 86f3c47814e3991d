"""Prints a simulation registering N scalar forces f0..f(N-1), one a line
from line 4, and a kernel writing each (used by diagnostics/force-limit.cpp)."""
import sys

n = int(sys.argv[1])
print("#include <wash/wash.hpp>")
print("void Update(wash::Particle &p);")
print("int main() {")
for i in range(n):
    print(f'  wash::add_force("f{i}", 1);')
print("  wash::add_update_kernel(&Update);")
print("  wash::start();")
print("}")
print("void Update(wash::Particle &p) {")
for i in range(n):
    print(f'  p.set_force_scalar("f{i}", 1.0);')
print("}")
