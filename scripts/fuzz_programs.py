#!/usr/bin/env python3
"""Random valid wash simulations, translated and compared with the reference.

Writes --count programs (a .cpp and a user header each) from --seed, builds
each as a reference and for every backend named in one CMake project against
an installed or built wash (-Dwash_DIR), runs them and compares each --dump
with the reference's byte for byte. Per program it prints one line per
backend: ok, rejected (a located translator error: allowed), and findings:
unlocated rejection, build failure, crash, dump differs. Exits 1 on any
finding. Standard library only.

    scripts/fuzz_programs.py --wash-dir build --seed 1 --count 20 --out /tmp/fuzz
"""
import argparse
import os
import random
import re
import shutil
import subprocess
import sys

MAX_DEPTH = 3
# The init kernel's jitter: wash::random, or (--no-wash-random, for wash
# builds older than it) a hash written in the program.
RANDOM = "wash::random"
HASH_HELPER = """double hash01(long k, long s) {
    unsigned long x = (unsigned long)k * 2654435761ul + (unsigned long)s * 40503ul;
    x ^= x >> 13; x *= 0x5bd1e995ul; x ^= x >> 15;
    return (double)(x % 1000003ul) / 1000003.0;
}
"""


class Program:
    """One random simulation; text() is its .cpp, header() its user header."""

    def __init__(self, rng, index, name):
        self.rng = rng
        self.name = name
        self.dim = rng.choice([2, 3])
        self.precision = rng.choice(["double", "float"])
        self.scalars = ["fs%d" % i for i in range(rng.randint(1, 3))]
        self.vectors = ["fv%d" % i for i in range(rng.randint(1, 2))]
        self.variables = ["var%d" % i for i in range(rng.randint(1, 3))]
        self.side = rng.randint(4, 7) if self.dim == 3 else rng.randint(8, 14)
        self.count = self.side ** self.dim
        self.periodic = rng.random() < 0.3
        self.jitter = rng.random() < 0.6
        self.index = index
        # A helper's name parameter must be the same constant at every call.
        self.named_force = rng.choice(self.scalars)

    # -- expressions -------------------------------------------------------
    def vec(self, axis):
        return "wash::Vec%dD{%s}" % (self.dim, ", ".join(axis(i) for i in range(self.dim)))

    def leaf(self, who="p"):
        r = self.rng
        choices = [
            lambda: repr(round(r.uniform(-1.5, 1.5), 3)),
            lambda: "%s.get_density()" % who,
            lambda: "%s.get_mass()" % who,
            lambda: "%s.get_vel().at(%d)" % (who, r.randrange(self.dim)),
            lambda: "%s.get_pos().at(%d)" % (who, r.randrange(self.dim)),
            lambda: "%s.get_vel().magnitude()" % who,
            lambda: "GAIN",
            lambda: "HDR_SCALE",
        ]
        if who == "p":
            choices += [
                lambda: "clampv(p.get_force_scalar(\"%s\"))" % r.choice(self.scalars),
                lambda: "force_of(p)",
                lambda: "clampv(p.get_force_scalar(FIRST_FORCE))",
                lambda: "force_of(p, \"%s\", %s)" % (self.scalars[0], round(r.uniform(0.1, 1), 2)),
                lambda: "force_of_s(p, std::string(\"%s\"))" % self.named_force,
                lambda: "var_of(\"%s\")" % r.choice(self.variables),
                lambda: "var_of(\"%s\", 2.0)" % r.choice(self.variables),
                lambda: "clampv(p.get_force_vector(\"%s\").at(%d))" % (r.choice(self.vectors),
                                                                       r.randrange(self.dim)),
            ]
        return r.choice(choices)()

    def expr(self, depth=0, who="p"):
        r = self.rng
        if depth >= MAX_DEPTH or r.random() < 0.3:
            return self.leaf(who if r.random() < 0.7 else "p")
        a = lambda: self.expr(depth + 1, who)
        forms = [
            lambda: "(%s + %s)" % (a(), a()),
            lambda: "(%s - %s)" % (a(), a()),
            lambda: "clampv(%s * %s)" % (a(), a()),
            lambda: "%s * GAIN" % a(),
            lambda: "GAIN * %s" % a(),
            lambda: "damp(%s)" % a(),
            lambda: "safe_div(%s, %s)" % (a(), a()),
            lambda: "soft(%s)" % a(),
            lambda: "soft(%s, %s)" % (a(), round(r.uniform(1, 3), 2)),
            lambda: "clampv(%s, %s)" % (a(), round(r.uniform(0.5, 4), 2)),
            lambda: "root1(%s)" % a(),
            lambda: "std::min(%s, %s)" % (a(), a()),
            lambda: "std::max(%s, %s)" % (a(), a()),
            lambda: "[](double x) { return 0.5 * x + 0.125; }(%s)" % a(),
            lambda: "[&](double x) { return x * %s; }(clampv(%s))" % (self.leaf(who), a()),
            lambda: "hdr_mix(%s, %s)" % (a(), a()),
            lambda: "nest(%s)" % a(),
            lambda: "nest(%s, %s)" % (a(), round(r.uniform(1, 2), 2)),
        ]
        if who == "p":
            forms.append(lambda: "with_force(p, %s)" % a())
        return r.choice(forms)()

    # -- kernels -----------------------------------------------------------
    def force_kernel(self, k):
        r = self.rng
        scalar, vector = r.choice(self.scalars), r.choice(self.vectors)
        return """void Force%d(wash::Particle& p, const std::vector<wash::Particle>& ns) {
    double acc = 0.0;
    wash::ParticleVec push{};
    for (const auto& n : ns) {
        const double r = (n.get_pos() - p.get_pos()).magnitude();
        const double w = std::max(0.0, 1.0 - r / RADIUS);
        acc += w * clampv(%s);
        push += (p.get_pos() - n.get_pos()) * (w * clampv(%s));
    }
    p.set_force_scalar("%s", clampv(%s, 50.0));
    p.set_force_vector("%s", push);
%s}
""" % (k, self.expr(1, "n"), self.expr(1, "n"), scalar,
       r.choice(["acc", "acc * GAIN", "acc + %s" % self.expr(2)]), vector, self.write_all(k, scalar, vector))

    def write_all(self, k, scalar, vector):
        # The first force kernel writes every force: one never written is rejected.
        if k != 0:
            return ""
        lines = ["    p.set_force_scalar(\"%s\", clampv(acc * %s));\n" % (s, round(self.rng.uniform(-1, 1), 2))
                 for s in self.scalars if s != scalar]
        lines += ["    p.set_force_vector(\"%s\", push * %s);\n" % (v, round(self.rng.uniform(-1, 1), 2))
                  for v in self.vectors if v != vector]
        return "".join(lines)

    def update_kernel(self, k):
        r = self.rng
        vector = r.choice(self.vectors)
        lines = ["void Update%d(wash::Particle& p) {" % k]
        lines.append("    const double a = clampv(%s);" % self.expr())
        if r.random() < 0.6:
            lines.append("    p.set_density(std::max(0.1, std::min(10.0, p.get_density() + 0.1 * a)));")
        if r.random() < 0.3:
            lines.append("    p.set_mass(1.0 + 0.5 * soft(a));")
        if r.random() < 0.5:
            lines.append("    p.set_force_scalar(\"%s\", %s);" % (r.choice(self.scalars), self.expr(1)))
        lines.append("    wash::ParticleVec v = p.get_vel() * 0.9 + p.get_force_vector(\"%s\") * (DT * GAIN);"
                     % vector)
        lines.append("    v += %s * (DT * a);" % self.vec(lambda i: "clampv(%s)" % self.expr(2)))
        lines.append("    p.set_vel(%s);" % self.vec(lambda i: "clampv(v.at(%d), 3.0)" % i))
        lines.append("    p.set_pos(p.get_pos() + p.get_vel() * DT);")
        lines.append("}")
        return "\n".join(lines) + "\n"

    def reduction_kernel(self, k):
        return "double Reduce%d(const wash::Particle& p) { return %s; }\n" % (k, self.expr(1))

    # -- files -------------------------------------------------------------
    def header(self):
        # No include guard: included twice, everything here may be repeated.
        return """// User header of %s: included twice, no guard.
#define HDR_SCALE 0.75
double hdr_mix(double a, double b);
using hdr_real = double;
""" % self.name

    def text(self):
        r = self.rng
        spacing = 1.0 / self.side
        radius = round(spacing * r.uniform(1.3, 2.2), 4)
        axes = [("(k %% SIDE)", 1), ("((k / SIDE) %% SIDE)", 2), ("(k / (SIDE * SIDE))", 3)][:self.dim]
        coords = []
        for i, (cell, stream) in enumerate(axes):
            jitter = " + 0.3 * (%s(k, %d) - 0.5)" % (RANDOM, stream) if self.jitter else ""
            coords.append("(%s + 0.5%s) * SPACING" % (cell.replace("%%", "%"), jitter))
        vel = ", ".join("0.1 * (%s(k, %d) - 0.5)" % (RANDOM, 10 + i) for i in range(self.dim))
        out = []
        w = out.append
        w("// Random wash program %s (scripts/fuzz_programs.py).\n" % self.name)
        w("#include <wash/wash.hpp>\n\n#include \"%s.hpp\"\n#include \"%s.hpp\"\n\n" % (self.name, self.name))
        w("#include <algorithm>\n#include <cmath>\n#include <string>\n#include <vector>\n\n")
        w("#define GAIN %s\n#define DAMP(x) ((x) * 0.9)\n" % round(r.uniform(0.2, 0.9), 3))
        w("#define SAFE_DIV(a, b) ((a) / (1.0 + (b) * (b)))\n\n")
        w("constexpr const char* FIRST_FORCE = \"%s\";\n" % self.scalars[0])
        w("constexpr int SIDE = %d;\nconstexpr double SPACING = %r;\n" % (self.side, spacing))
        w("constexpr double RADIUS = %r;\nconstexpr double DT = 0.01;\n\n" % radius)
        if RANDOM != "wash::random":
            w(HASH_HELPER)
        w("double hdr_mix(double a, double b) { return 0.5 * a - 0.25 * b; }\n")
        w("double clampv(double x, double lim = 4.0) { return std::min(std::max(x, -lim), lim); }\n")
        w("double soft(double x, double k = 1.0) { return x / (k + x * x); }\n")
        w("double force_of(const wash::Particle& p, const char* name = \"%s\", double scale = 1.0) {\n"
          "    return clampv(p.get_force_scalar(name)) * scale;\n}\n" % self.scalars[0])
        w("double force_of_s(const wash::Particle& p, const std::string& name) {\n"
          "    return clampv(p.get_force_scalar(name));\n}\n")
        w("double var_of(const std::string& name, double lim = 8.0) {\n"
          "    return clampv(wash::get_variable(name), lim);\n}\n")
        # Function-like macros only in helper bodies: a particle access in a
        # macro argument is a located rejection (CodegenInMacro), by design.
        w("double damp(double x) { return DAMP(x); }\n")
        w("double safe_div(double a, double b) { return SAFE_DIV(a, b); }\n")
        w("double root1(double x) { return std::sqrt(1.0 + x * x); }\n")
        w("double nest(double x, hdr_real k = 1.0) { return soft(hdr_mix(x, k), k + 0.5); }\n")
        w("double with_force(const wash::Particle& p, double x) { return nest(force_of(p) + x); }\n\n")
        w("void Spawn() {\n    for (int k = 0; k < %d; k++) {\n" % self.count)
        for i, c in enumerate(coords):
            w("        const double x%d = %s;\n" % (i, c))
        w("        wash::create_particle(1.0 + 0.1 * (k %% 3), 1.0, SPACING, %s,\n"
          "                              wash::Vec%dD{%s});\n    }\n}\n\n"
          % (self.vec(lambda i: "x%d" % i), self.dim, vel))
        kernels = []
        for k in range(r.randint(1, 2)):
            w(self.force_kernel(k))
            kernels.append("    wash::add_force_kernel(&Force%d);\n" % k)
        for k in range(r.randint(1, 2)):
            w(self.update_kernel(k))
            kernels.append("    wash::add_update_kernel(&Update%d);\n" % k)
        for k, var in enumerate(self.variables):
            w(self.reduction_kernel(k))
            op = r.choice(["Sum", "Min", "Max"])
            kernels.insert(r.randrange(len(kernels) + 1),
                           "    wash::add_reduction_kernel(&Reduce%d, wash::Reduction::%s, \"%s\");\n"
                           % (k, op, var))
        w("void Tick() {\n    wash::set_variable(\"%s\", clampv(wash::get_variable(\"%s\") * 0.5 + %s));\n}\n\n"
          % (self.variables[0], self.variables[-1], round(r.uniform(-1, 1), 3)))
        kernels.insert(r.randrange(len(kernels) + 1), "    wash::add_void_kernel(&Tick);\n")
        w("int main() {\n")
        if self.precision == "float":
            w("    wash::set_precision(\"float\");\n")
        w("    wash::set_influence_radius(RADIUS);\n")
        if self.periodic:
            lo = ", ".join(["0.0"] * self.dim)
            hi = ", ".join(["1.0"] * self.dim)
            per = ", ".join(["true"] + ["false"] * (self.dim - 1))
            w("    wash::set_bounding_box({%s}, {%s}, {%s});\n" % (lo, hi, per))
        for s in self.scalars:
            w("    wash::add_force(\"%s\", 1);\n" % s)
        for v in self.vectors:
            w("    wash::add_force(\"%s\", %d);\n" % (v, self.dim))
        for v in self.variables:
            w("    wash::add_variable(\"%s\", %s);\n" % (v, round(r.uniform(-1, 1), 3)))
        w("    wash::add_init_kernel(&Spawn);\n")
        w("".join(kernels))
        w("    wash::set_max_iterations(%d);\n    wash::start();\n}\n" % r.randint(3, 6))
        return "".join(out)


def generate(seed, count, out):
    programs = []
    for i in range(count):
        name = "fuzz_%d_%d" % (seed, i)
        prog = Program(random.Random("%d/%d" % (seed, i)), i, name)
        folder = os.path.join(out, "src", name)
        os.makedirs(folder, exist_ok=True)
        with open(os.path.join(folder, name + ".cpp"), "w") as f:
            f.write(prog.text())
        with open(os.path.join(folder, name + ".hpp"), "w") as f:
            f.write(prog.header())
        programs.append(prog)
    return programs


def run(cmd, log, timeout=120, env=None):
    """Runs cmd, writing its output to log; returns the exit status (124 on timeout)."""
    with open(log, "w") as f:
        try:
            return subprocess.run(cmd, stdout=f, stderr=subprocess.STDOUT, timeout=timeout,
                                  env=env).returncode
        except subprocess.TimeoutExpired:
            return 124


def tail(path, lines=6):
    with open(path, errors="replace") as f:
        return " | ".join(l.rstrip() for l in f.readlines()[-lines:])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--count", type=int, default=3)
    parser.add_argument("--out", required=True)
    parser.add_argument("--backends", default="serial,openmp,mpi")
    parser.add_argument("--wash-dir", required=True, help="wash_DIR: a wash build or package folder")
    parser.add_argument("--mpiexec", default="mpirun")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--no-wash-random", action="store_true",
                        help="jitter with a hash in the program (wash builds without wash::random)")
    parser.add_argument("--keep", action="store_true", help="keep --out afterwards")
    args = parser.parse_args()
    if args.no_wash_random:
        global RANDOM
        RANDOM = "hash01"
    sys.stdout.reconfigure(line_buffering=True)
    backends = [b for b in args.backends.split(",") if b]
    out = os.path.abspath(args.out)
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    programs = generate(args.seed, args.count, out)

    cmake = ["cmake_minimum_required(VERSION 3.20)", "project(wash_fuzz LANGUAGES CXX)",
             "find_package(wash REQUIRED CONFIG)"]
    for p in programs:
        src = "%s/%s.cpp" % (p.name, p.name)
        cmake.append("wash_add_reference(%s-reference SOURCE %s DIM %d)" % (p.name, src, p.dim))
        for b in backends:
            cmake.append("wash_add_simulation(%s-%s SOURCE %s BACKEND %s)" % (p.name, b, src, b))
    with open(os.path.join(out, "src", "CMakeLists.txt"), "w") as f:
        f.write("\n".join(cmake) + "\n")
    bld = os.path.join(out, "build")
    logs = os.path.join(out, "logs")
    os.makedirs(logs)
    if run(["cmake", "-S", os.path.join(out, "src"), "-B", bld, "-G", "Ninja",
            "-DCMAKE_BUILD_TYPE=Release", "-Dwash_DIR=" + os.path.abspath(args.wash_dir)],
           os.path.join(logs, "configure.txt"), timeout=300) != 0:
        print("configure failed: " + tail(os.path.join(logs, "configure.txt")))
        return 2
    run(["cmake", "--build", bld, "-j%d" % args.jobs, "--", "-k", "0"],
        os.path.join(logs, "build.txt"), timeout=3600)

    passed = failed = 0
    for p in programs:
        src = os.path.join(out, "src", p.name, p.name + ".cpp")
        print("%s: %dD %s, %d particles%s" % (p.name, p.dim, p.precision, p.count,
                                              ", periodic x" if p.periodic else ""))
        findings = []
        work = os.path.join(out, "runs", p.name)
        os.makedirs(work)
        reference = os.path.join(bld, p.name + "-reference")
        ref_dump = os.path.join(work, "reference.csv")
        if not os.path.exists(reference):
            findings.append("reference: build failure (the generated program is not valid C++?)")
        else:
            status = run([reference, "--quiet", "--dump", ref_dump, "--out", os.path.join(work, "ref")],
                         os.path.join(work, "reference.txt"))
            if status != 0:
                findings.append("reference: exit %d (an invalid program: a generator bug): %s"
                                % (status, tail(os.path.join(work, "reference.txt"))))
            elif re.search(r"\b(nan|inf)\b", open(ref_dump).read(), re.I):
                findings.append("reference: non-finite values (generator bug)")
        for b in backends if not findings else []:
            target = "%s-%s" % (p.name, b)
            exe = os.path.join(bld, target)
            if not os.path.exists(exe):
                # Again alone, for its messages (and past a transient failure).
                log = os.path.join(work, b + "-build.txt")
                if run(["cmake", "--build", bld, "--target", target], log, timeout=600) == 0:
                    print("  %s: built only on a second try (see logs/build.txt)" % b)
            if not os.path.exists(exe):
                generated = os.path.join(bld, target + ".wash", p.name + "." + b + ".cpp")
                text = open(log, errors="replace").read()
                if os.path.exists(generated):
                    findings.append("%s: build failure: %s" % (b, tail(log, 12)))
                else:
                    located = re.search(re.escape(src) + r":\d+:\d+: error: .*", text)
                    if located:
                        print("  %s: rejected: %s" % (b, located.group(0)))
                    else:
                        findings.append("%s: rejected without a location: %s" % (b, tail(log, 12)))
                continue
            dump = os.path.join(work, b + ".csv")
            cmd = [exe, "--quiet", "--dump", dump, "--out", os.path.join(work, b)]
            env = dict(os.environ, OMP_NUM_THREADS="2")
            if b == "mpi":
                env["OMP_NUM_THREADS"] = "1"
                cmd = [args.mpiexec, "--allow-run-as-root", "--oversubscribe", "-np", "2"] + cmd
            log = os.path.join(work, b + ".txt")
            status = run(cmd, log, env=env)
            if status != 0:
                findings.append("%s: crash or error, exit %d: %s" % (b, status, tail(log)))
            elif os.path.exists(ref_dump):
                with open(ref_dump, "rb") as f1, open(dump, "rb") as f2:
                    a, c = f1.read().splitlines(), f2.read().splitlines()
                if a != c:
                    line = next((i for i, (x, y) in enumerate(zip(a, c)) if x != y), min(len(a), len(c)))
                    findings.append("%s: dump differs from the reference at line %d of %d: %s vs %s"
                                    % (b, line + 1, len(a), a[line][:160] if line < len(a) else "EOF",
                                       c[line][:160] if line < len(c) else "EOF"))
                else:
                    print("  %s: ok" % b)
        for f in findings:
            print("  FINDING %s" % f)
        if findings:
            failed += 1
            print("  reproduce: %s (with %s.hpp next to it)" % (src, p.name))
        else:
            passed += 1
    print("%d passed, %d failed" % (passed, failed))
    if not args.keep and failed == 0:
        shutil.rmtree(out, ignore_errors=True)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
