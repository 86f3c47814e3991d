// A field a force kernel writes on its own particle and reads on neighbours
// needs a snapshot; a field only written (density) or only read on
// neighbours (pos) does not.
// RUN: %wash --dump-model %s | FileCheck %s
#include <wash/wash.hpp>

void kernel(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  wash::Vec2D v = p.get_vel();
  for (const auto &n : ns)
    v += n.get_vel() * n.get_pos().at(0);
  p.set_vel(v);
  p.set_density(p.get_density() + 1);
}

int main() {
  wash::add_force_kernel(&kernel);
  wash::start();
}
// CHECK:      neighbour-reads: pos vel
// CHECK-NEXT: hazards: vel
