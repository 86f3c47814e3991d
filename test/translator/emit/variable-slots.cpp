// get_variable with a name the translator knows reads a slot, not the map of
// names: `wash::get_variable(wash_gen::var_x)`, the callee and parenthesis
// where they were (so an error reports the same column). The storage header
// declares each slot once, in order of first use, with the name escaped; the
// driver binds them when start() begins. A name known only at run time, and
// a macro argument, keep the lookup. (Each check is anchored at the start of
// a line: the generated file keeps these comments.)
// RUN: rm -rf %t && %wash --backend=serial -o %t %s 2>&1 | count 0
// RUN: %cxx_check -I%t %t/variable-slots.serial.cpp
// RUN: FileCheck %s --check-prefix=SOURCE < %t/variable-slots.serial.cpp
// RUN: FileCheck %s --check-prefix=HEADER < %t/variable-slots.wash.hpp
#include <wash/wash.hpp>

#include <string>
#include <vector>

#define SPEED "speed"

constexpr const char *gainName = "gain";

// SOURCE: {{^}}double gain() { return wash::get_variable(wash_gen::var_gain); }
double gain() { return wash::get_variable(gainName); }

void Drift(wash::Particle &p) {
  // The rewrite moves the call on its line: its CallSite is written out, at
  // the call's place in this file (start of the call, then parenthesis).
  // SOURCE: {{^ +}}wash_gen::P.pos[p] = wash_gen::P.pos[p] + wash_gen::P.vel[p] * (wash::get_variable(wash_gen::var_speed, wash::CallSite::written(__FILE__, 28, 42, 28, 60)) * gain())
  p.set_pos(p.get_pos() + p.get_vel() * (wash::get_variable("speed") * gain()));
}

void Crowd(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  double near = 0.0;
  for (const auto &n : ns)
    // SOURCE: {{^ +}}near += ns.distance(n) * wash::get_variable(wash_gen::var706172742032, wash::CallSite::written(__FILE__, 35, 55, 35, 73));
    near += (p.get_pos() - n.get_pos()).magnitude() * wash::get_variable("part 2");
  const std::string name = p.get_density() > 1.0 ? "gain" : "speed";
  // SOURCE: {{^ +}}wash_gen::P.density[p] = near + wash::get_variable(SPEED, wash::CallSite::written(__FILE__, 38, 24, 38, 42)) + wash::get_variable(name, wash::CallSite::written(__FILE__, 38, 52, 38, 70))
  p.set_density(near + wash::get_variable(SPEED) + wash::get_variable(name));
}

void Damp() {
  // SOURCE: {{^ +}}wash::set_variable("speed", 0.99 * wash::get_variable(wash_gen::var_speed));
  wash::set_variable("speed", 0.99 * wash::get_variable("speed"));
}

int main() {
  wash::set_influence_radius(0.5);
  wash::add_variable("speed", 1.0);
  wash::add_variable("gain", 0.5);
  wash::add_variable("part 2", 2.0);
  // SOURCE: {{^ +}}wash::set_variable("gain", wash::get_variable(wash_gen::var_gain) * 2.0);
  wash::set_variable("gain", wash::get_variable("gain") * 2.0);
  wash::add_update_kernel(&Drift);
  wash::add_force_kernel(&Crowd);
  wash::add_void_kernel(&Damp);
  wash::start();
}
// SOURCE: {{^}}void start() {
// SOURCE-NEXT: {{^ +}}const wash::backend::Translation translated
// SOURCE: {{^ +}}wash::backend::Run run(translated, backend.writes());
// SOURCE-NEXT: {{^ +}}wash::backend::bindVariables({&var_gain, &var_speed, &var706172742032});

// HEADER: {{^}}inline wash::backend::VariableSlot var_gain{"gain", 4};
// HEADER-NEXT: {{^}}inline wash::backend::VariableSlot var_speed{"speed", 5};
// HEADER-NEXT: {{^}}inline wash::backend::VariableSlot var706172742032{"part 2", 6};
