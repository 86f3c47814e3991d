// Every way the analysis accepts of reaching a neighbour (index, at, front,
// back, iterators and ->, std::for_each with a lambda, copies, pointers,
// helpers taking the list) survives code generation: the generated program
// compiles for each backend.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %wash --backend=serial -o %t/serial %S/../analysis/access-neighbour-forms.cpp 2>/dev/null
// RUN: %cxx_check -I%t/serial %t/serial/access-neighbour-forms.serial.cpp
// RUN: %wash --backend=openmp -o %t/openmp %S/../analysis/access-neighbour-forms.cpp 2>/dev/null
// RUN: %cxx_check -I%t/openmp %t/openmp/access-neighbour-forms.openmp.cpp
// RUN: %wash --backend=mpi -o %t/mpi %S/../analysis/access-neighbour-forms.cpp 2>/dev/null
// RUN: %cxx_check -I%t/mpi %t/mpi/access-neighbour-forms.mpi.cpp
// RUN: %wash --backend=serial -o %t/helpers %S/../analysis/access-helper-parameter-binding.cpp 2>/dev/null
// RUN: %cxx_check -I%t/helpers %t/helpers/access-helper-parameter-binding.serial.cpp
// Lambdas the escape checks accept, and registrations guarded with start:
// RUN: %wash --backend=serial -o %t/lambdas %S/../analysis/lambda-through-std-function.cpp 2>/dev/null
// RUN: %cxx_check -I%t/lambdas %t/lambdas/lambda-through-std-function.serial.cpp
// RUN: %wash --backend=serial -o %t/flow %S/../settings/registration-flow-accepted.cpp 2>/dev/null
// RUN: %cxx_check -I%t/flow %t/flow/registration-flow-accepted.serial.cpp
