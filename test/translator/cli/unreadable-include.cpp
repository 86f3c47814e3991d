// What protects the simulation file protects every file the translation
// reads: an #include of a device, a FIFO, /dev/stdin or a file over 64 MB is
// an error at the #include, before clang opens the file (which would block
// or read without end).
// RUN: rm -rf %t && mkdir -p %t
// RUN: %expect_exit 1 %wash --dump-model %s -- '-DINCLUDED="/dev/zero"' 2>&1 \
// RUN:   | FileCheck %s --check-prefixes=AT,DEVICE -DFILE=/dev/zero
// RUN: %expect_exit 1 %wash --dump-model %s -- '-DINCLUDED="/dev/stdin"' < /dev/null 2>&1 \
// RUN:   | FileCheck %s --check-prefixes=AT,DEVICE -DFILE=/dev/stdin
// RUN: %expect_exit 1 %wash --dump-model %s -- '-DINCLUDED="/proc/self/fd/0"' < /dev/null 2>&1 \
// RUN:   | FileCheck %s --check-prefixes=AT,DEVICE -DFILE=/proc/self/fd/0
// RUN: mkfifo %t/fifo.h
// RUN: %expect_exit 1 %wash --dump-model %s -- '-DINCLUDED="%t/fifo.h"' 2>&1 \
// RUN:   | FileCheck %s --check-prefixes=AT,DEVICE -DFILE=%t/fifo.h
// RUN: truncate -s 65M %t/huge.h
// RUN: %expect_exit 1 %wash --dump-model %s -- '-DINCLUDED="%t/huge.h"' 2>&1 \
// RUN:   | FileCheck %s --check-prefixes=AT,HUGE
// The same through -include.
// RUN: %expect_exit 1 %wash --dump-model %s -- -include /dev/zero 2>&1 | FileCheck %s --check-prefix=DASH
// DASH: fatal error: cannot open file '/dev/zero': it is not a regular file
// A regular header is read as before.
// RUN: echo 'inline int included = 1;' > %t/plain.h
// RUN: %wash --dump-model %s -- '-DINCLUDED="%t/plain.h"' | FileCheck %s --check-prefix=PLAIN
// PLAIN: max-iterations: 1
// RUN: rm -rf %t
#include <wash/wash.hpp>

#ifdef INCLUDED
// AT: unreadable-include.cpp:[[@LINE+1]]:10: fatal error:
#include INCLUDED
#endif
// DEVICE-SAME: cannot open file '[[FILE]]': it is not a regular file (a device, FIFO or socket); wash reads only regular files
// HUGE-SAME: cannot open file '{{.*}}huge.h': it is larger than 64 MB; wash reads no larger file

void Heat(wash::Particle& p) { p.set_density(p.get_density() * 2.0); }

int main() {
  wash::set_influence_radius(0.1);
  wash::add_update_kernel(&Heat);
  wash::set_max_iterations(1);
  wash::start();
}
