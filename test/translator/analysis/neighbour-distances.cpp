// A magnitude of the offset between the particle and a neighbour that is an
// element of the list (loop variable by reference, ns[k], a reference to one),
// directly or through local variables never modified, reads the distance the
// search keeps; every other magnitude stays as written.
// RUN: %wash --dump-model %s 2>/dev/null | FileCheck %s
#include <wash/wash.hpp>
#include <vector>

// CHECK-LABEL: neighbour-distances: kept by the search

void locals(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  wash::Vec2D pos = p.get_pos();
  double sum = 0;
  for (const auto &n : ns) {
    wash::Vec2D there = n.get_pos();
    wash::Vec2D offset = there - pos;
    // CHECK-NEXT: locals @[[#@LINE+1]]:12: ns.distance(n) for p
    sum += offset.magnitude();
  }
  p.set_density(sum);
}

void direct(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  double sum = 0;
  for (auto &n : ns)
    // CHECK-NEXT: direct @[[#@LINE+1]]:12: ns.distance(n) for p
    sum += (p.get_pos() - n.get_pos()).magnitude();
  p.set_density(sum);
}

void indexed(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  double sum = 0;
  for (size_t k = 0; k < ns.size(); k++) {
    // CHECK-NEXT: indexed @[[#@LINE+1]]:12: ns.distance(ns[k]) for p
    sum += (ns[k].get_pos() - p.get_pos()).magnitude();
    const wash::Particle &n = ns[k];
    const wash::Vec2D d = p.get_pos() - n.get_pos();
    // CHECK-NEXT: indexed @[[#@LINE+1]]:12: ns.distance(n) for p
    sum += d.magnitude();
  }
  p.set_density(sum);
}

// CHECK-NEXT: around @[[#@LINE+3]]:35: ns.distance(n) for q if it is the own particle
double around(const wash::Particle &q, const std::vector<wash::Particle> &ns) {
  double sum = 0;
  for (const auto &n : ns) sum += (q.get_pos() - n.get_pos()).magnitude();
  return sum;
}

// Left as written, each for its own reason.
void refused(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  double sum = around(p, ns);
  for (auto n : ns) // a copy: not an element of the list
    sum += (p.get_pos() - n.get_pos()).magnitude();
  for (const auto &n : ns) {
    wash::Vec2D d = p.get_pos() - n.get_pos();
    d = d * 0.5; // modified
    sum += d.magnitude();
    auto f = [&](const wash::Particle &m) { return (m.get_pos() - p.get_pos()).magnitude(); };
    sum += f(n);                                            // in a lambda
    sum += (ns[0].get_pos() - n.get_pos()).magnitude();     // two neighbours
    sum += (n.get_vel() - p.get_vel()).magnitude();         // not positions
    static wash::Vec2D first = p.get_pos();                 // not per call
    sum += (n.get_pos() - first).magnitude();
    wash::Vec2D mine = p.get_pos();
    *(mine[0]) = 0.0; // written through a pointer to a component
    sum += (n.get_pos() - mine).magnitude();
    sum += d.dot(d);
  }
  for (size_t k = 0; k < ns.size(); k++) {
    wash::Vec2D d = ns[k].get_pos() - p.get_pos(); // k could change before the magnitude
    sum += d.magnitude();
  }
  p.set_density(sum);
}
// CHECK-NOT: {{.}}

int main() {
  wash::set_influence_radius(0.1);
  wash::add_force_kernel(&locals);
  wash::add_force_kernel(&direct);
  wash::add_force_kernel(&indexed);
  wash::add_force_kernel(&refused);
  wash::start();
}
