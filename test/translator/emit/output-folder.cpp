// wash never overwrites a file it did not write: it writes only into a new
// or empty folder or into a previous wash project (marked by the
// .wash-project file it writes), and there it keeps the user's own files.
// RUN: rm -rf %t && mkdir -p %t/user
// RUN: echo "the user's own" > %t/user/CMakeLists.txt
// RUN: %expect_exit 1 %wash -o %t/user %s 2>&1 | FileCheck %s --check-prefix=FOREIGN
// The default -o . is the same folder.
// RUN: cd %t/user && %expect_exit 1 %wash %s 2>&1 | FileCheck %s --check-prefix=FOREIGN
// FOREIGN: wash: error: output folder '{{.*}}' is not empty and holds no wash project (no '.wash-project' file); wash never overwrites files it did not write: choose a new or empty folder with -o
// RUN: grep -qx "the user's own" %t/user/CMakeLists.txt
// RUN: ls -A %t/user | FileCheck %s --check-prefix=UNTOUCHED
// UNTOUCHED: {{^CMakeLists.txt$}}
// UNTOUCHED-NOT: {{.}}
//
// A previous project is replaced; what the user added to it stays, and what
// wash no longer generates goes.
// RUN: %wash --backend=serial -o %t/proj %s 2>/dev/null
// RUN: mkdir %t/proj/build && echo mine > %t/proj/build/notes.txt && echo mine > %t/proj/README
// RUN: %wash --backend=openmp -o %t/proj %s 2>/dev/null
// RUN: ls -A %t/proj | FileCheck %s --check-prefix=REPLACED
// REPLACED: .wash-project
// REPLACED-NEXT: CMakeLists.txt
// REPLACED-NEXT: README
// REPLACED-NEXT: build
// REPLACED-NEXT: output-folder.openmp.cpp
// REPLACED-NEXT: output-folder.wash.hpp
// REPLACED-NOT: {{.}}
// RUN: grep -qx mine %t/proj/build/notes.txt && grep -qx mine %t/proj/README
// A file of the user's that wash would now generate is not overwritten.
// RUN: echo mine > %t/proj/output-folder.serial.cpp
// RUN: %expect_exit 1 %wash --backend=serial -o %t/proj %s 2>&1 | FileCheck %s --check-prefix=THEIRS
// THEIRS: wash: error: '{{.*}}output-folder.serial.cpp' was not written by wash; it is not overwritten
// RUN: grep -qx mine %t/proj/output-folder.serial.cpp
//
// The working folder (-o .), empty or a previous project, is filled in place.
// RUN: mkdir %t/here && cd %t/here && %wash %s 2>/dev/null && %wash --backend=openmp %s 2>/dev/null
// RUN: ls -A %t/here | FileCheck %s --check-prefix=HERE
// HERE: .wash-project
// HERE-NEXT: CMakeLists.txt
// HERE-NEXT: output-folder.openmp.cpp
// HERE-NEXT: output-folder.wash.hpp
// HERE-NOT: {{.}}
//
// A project written before wash wrote its marker is known by the banner atop
// its files: it is replaced, and its build folder stays.
// RUN: %wash --backend=serial -o %t/old %s 2>/dev/null && rm %t/old/.wash-project
// RUN: mkdir %t/old/build && echo mine > %t/old/build/notes.txt
// RUN: %wash --backend=openmp -o %t/old %s 2>/dev/null
// RUN: ls -A %t/old | FileCheck %s --check-prefix=UNMARKED
// UNMARKED: .wash-project
// UNMARKED-NEXT: CMakeLists.txt
// UNMARKED-NEXT: build
// UNMARKED-NEXT: output-folder.openmp.cpp
// UNMARKED-NEXT: output-folder.wash.hpp
// UNMARKED-NOT: {{.}}
// RUN: grep -qx mine %t/old/build/notes.txt
// There too a file without the banner is the user's.
// RUN: %wash --backend=serial -o %t/old2 %s 2>/dev/null && rm %t/old2/.wash-project
// RUN: echo mine > %t/old2/output-folder.wash.hpp
// RUN: %expect_exit 1 %wash --backend=serial -o %t/old2 %s 2>&1 | FileCheck %s --check-prefix=UNBANNERED
// UNBANNERED: wash: error: '{{.*}}old2/output-folder.wash.hpp' was not written by wash; it is not overwritten
// RUN: grep -qx mine %t/old2/output-folder.wash.hpp
#include <wash/wash.hpp>

void Heat(wash::Particle& p) { p.set_density(p.get_density() * 2.0); }

int main() {
  wash::set_influence_radius(0.1);
  wash::add_update_kernel(&Heat);
  wash::set_max_iterations(1);
  wash::start();
}
