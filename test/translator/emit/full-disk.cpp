// Writing the generated project onto a full disk fails at once with "No
// space left on device" and exit status 1, and leaves no partial project: a
// previous project stays as it was, a new folder is not created.
// REQUIRES: root
// RUN: python3 %S/../Inputs/full_disk.py %wash %t | FileCheck %s
// CHECK: previous project:
// CHECK-NEXT: exit 0: no error
// CHECK-NEXT: over the previous project:
// CHECK-NEXT: exit 1: wash: error: cannot write '{{.*}}': No space left on device
// CHECK-NEXT: previous project unchanged
// CHECK-NEXT: into a new folder:
// CHECK-NEXT: exit 1: wash: error: cannot write '{{.*}}': No space left on device
// CHECK-NEXT: left on the disk: fill proj{{$}}
