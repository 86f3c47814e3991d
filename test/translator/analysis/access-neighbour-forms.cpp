// Every way of reaching a neighbour: indexing with size(), at(), iterators,
// std::for_each with a lambda, a local reference, a copy, a pointer, and a
// helper that takes the neighbour vector. Each reads a different property so
// that a form the analysis misses shows up as a missing name.
// RUN: %wash --dump-model %s | FileCheck %s
#include <wash/wash.hpp>

#include <algorithm>

double smoothing(const std::vector<wash::Particle> &ns) {
  double h = 0;
  for (std::size_t k = 0; k < ns.size(); ++k)
    h += ns[k].get_smoothing_length();
  return h;
}

void kernel(wash::Particle &self, const std::vector<wash::Particle> &neighbours) {
  double d = 0;
  for (std::size_t k = 0; k < neighbours.size(); ++k)
    d += neighbours[k].get_density();
  if (!neighbours.empty())
    d += neighbours.at(0).get_mass();
  for (auto it = neighbours.begin(); it != neighbours.end(); ++it)
    d += it->get_vel().at(0);
  std::for_each(neighbours.begin(), neighbours.end(),
                [&](const wash::Particle &n) { d += n.get_force_scalar("heat"); });
  const wash::Particle &first = neighbours.front();
  wash::Particle copy = first;
  const wash::Particle *ptr = &copy;
  d += ptr->get_acc().at(1) + smoothing(neighbours);
  auto readPos = [](const wash::Particle &n) { return n.get_pos(); };
  d += readPos(neighbours.back()).at(0);
  self.set_force_scalar("heat", d);
}

int main() {
  wash::add_force("heat", 1);
  wash::add_force_kernel(&kernel);
  wash::start();
}
// CHECK:      0: force kernel
// CHECK-NEXT:   own-reads: -
// CHECK-NEXT:   own-writes: heat
// CHECK-NEXT:   always-writes: heat
// CHECK-NEXT:   neighbour-reads: pos vel acc density mass smoothing_length heat
// CHECK-NEXT:   hazards: heat
