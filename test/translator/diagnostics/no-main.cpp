// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
// CHECK: no-main.cpp:1:1: error: no 'main' function is defined in this file; wash reads the simulation from 'main'
#include <wash/wash.hpp>

void update(wash::Particle &p) { p.set_mass(1); }
