// RUN: %expect_exit 1 %wash --dump-model %t.does-not-exist.cpp 2>&1 | FileCheck %s
// CHECK: wash: error: cannot read '{{.*}}does-not-exist.cpp': No such file or directory
