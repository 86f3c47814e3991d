# lit configuration of the translator tests: test/translator/<stage>/*.cpp.
import os
import lit.formats

config.name = "wash-translator"
config.test_format = lit.formats.ShTest(execute_external=False)
config.suffixes = [".cpp"]
config.test_source_root = os.path.dirname(__file__)
config.test_exec_root = config.wash_obj_root
# Inputs/ holds files that tests include or run on; unit/ and frontend/ are
# GoogleTest.
config.excludes = ["Inputs", "unit", "frontend", "CMakeLists.txt"]

config.substitutions.append(("%wash_src", config.wash_src_root))
config.substitutions.append(("%wash", config.wash_bin))
config.environment["PATH"] = os.pathsep.join(
    [config.llvm_tools_dir, config.environment.get("PATH", os.environ.get("PATH", ""))])
# Diagnostics without colour, and no locale-dependent messages.
config.environment["TERM"] = "dumb"
# %expect_exit N cmd: cmd must exit with N, never crash, and print nothing on
# stdout when N != 0; its stderr and stdout are passed on for FileCheck.
config.substitutions.insert(0, ("%expect_exit", "python3 " +
    os.path.join(config.test_source_root, "Inputs", "expect_exit.py")))

# %cxx_check FILE: the generated code compiles against the backend runtimes.
_includes = " ".join("-I" + os.path.join(config.wash_src_root, d) for d in
    ["runtime/include", "backends/common/include"] +
    ["backends/%s/include" % b for b in config.wash_backends])
# REQUIRES: backend-<name>, one feature per line of backends/backends.def.
for _backend in config.wash_backends:
    config.available_features.add("backend-" + _backend)
config.substitutions.append(
    ("%cxx_check", config.cxx + " -std=c++20 -fsyntax-only -fopenmp " + _includes))

# REQUIRES: root, for tests that mount a small tmpfs (a full disk).
if hasattr(os, "geteuid") and os.geteuid() == 0:
    config.available_features.add("root")
# %cxx: the C++ compiler this build uses, to build generated projects (after
# %cxx_check, which it is a prefix of).
config.substitutions.append(("%cxx", config.cxx))
