// Inputs clang would read forever or that exhaust memory are refused before
// parsing, with a message and exit status 1: devices, FIFOs, directories and
// files over 64 MB.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %expect_exit 1 %wash --dump-model /dev/zero 2>&1 | FileCheck %s --check-prefix=DEVICE
// DEVICE: wash: error: cannot read {{.*}}: it is not a regular file
// RUN: mkfifo %t/fifo.cpp
// RUN: %expect_exit 1 %wash --dump-model %t/fifo.cpp 2>&1 | FileCheck %s --check-prefix=DEVICE
// RUN: %expect_exit 1 %wash --dump-model %t 2>&1 | FileCheck %s --check-prefix=DIR
// DIR: wash: error: cannot read '{{.*}}': it is a directory
// RUN: truncate -s 65M %t/huge.cpp
// RUN: %expect_exit 1 %wash --dump-model %t/huge.cpp 2>&1 | FileCheck %s --check-prefix=HUGE
// HUGE: wash: error: cannot read '{{.*}}huge.cpp': it is larger than 64 MB; wash reads no larger file
// RUN: rm -rf %t
