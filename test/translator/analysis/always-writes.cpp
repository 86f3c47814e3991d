// A field counts as set on every path when the setter is a statement of the
// kernel's top level, or of a helper called there with the particle, before
// any statement that may return. After a search, the sort need not carry a
// field some later kernel of the iteration always sets before anything reads it.
// RUN: %wash --dump-model %s 2>/dev/null | FileCheck %s
#include <wash/wash.hpp>
#include <vector>

void setsMass(wash::Particle &q, double m) { q.set_mass(m); }
void maybeSetsAcc(wash::Particle &q) {
  if (q.get_density() > 1.0)
    return;
  q.set_acc(q.get_vel());
}

void Gather(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  double sum = 0;
  for (const auto &n : ns) {
    sum += n.get_mass();
    p.set_force_scalar("inLoop", sum); // in a loop
  }
  p.set_density(sum);
  { p.set_force_scalar("inBlock", 1.0); }
  setsMass(p, sum);
  if (sum > 2.0)
    p.set_force_scalar("inIf", 1.0);
  maybeSetsAcc(p); // not on every path through the helper
}

void Early(wash::Particle &p) {
  p.set_force_scalar("beforeReturn", 1.0);
  if (p.get_mass() > 0.0)
    return;
  p.set_force_scalar("afterReturn", 1.0);
}

void Reads(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  p.set_force_scalar("readFirst", p.get_force_scalar("readFirst") + ns.size());
  p.set_force_scalar("neighboursRead", ns.empty() ? 0.0 : ns[0].get_force_scalar("inBlock"));
}

int main() {
  wash::add_force_kernel(&Gather);
  wash::add_update_kernel(&Early);
  wash::add_force_kernel(&Reads);
  wash::start();
}
// CHECK:      0: force Gather
// CHECK:        always-writes: density mass inBlock
// CHECK:      1: update Early
// CHECK:        always-writes: beforeReturn
// CHECK:      2: force Reads
// CHECK:        always-writes: readFirst neighboursRead
// Gather reads density (in maybeSetsAcc) and its neighbours' mass, Reads its
// own readFirst: those move with the sort. inBlock is set by Gather before
// Reads reads it. acc, inLoop, inIf, afterReturn are not set on every path.
// CHECK:      rewritten-after-search: inBlock beforeReturn neighboursRead
