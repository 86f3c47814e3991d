// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
#include <wash/wash.hpp>

// CHECK: mixed-dimensions.cpp:[[@LINE+3]]:7: error: the simulation uses both 2-dimensional and 3-dimensional vectors
// CHECK: mixed-dimensions.cpp:[[@LINE+1]]:7: note: 2-dimensional vector used here
const wash::Vec2D flat{1.0, 2.0};
const wash::Vec3D deep{1.0, 2.0, 3.0};

int main() { wash::start(); }
