// --dump-after=<pass> prints the model right after that pass and stops: it
// has what that pass and the ones before it found, not what later ones derive
// (still at their defaults), and writes no files. After the last pass it is
// --dump-model.
// RUN: %wash --dump-after=detect-dimension %s | FileCheck %s --check-prefix=DIM
// RUN: %wash --dump-after=collect-simulation %s | FileCheck %s --check-prefix=COLLECT
// RUN: %wash --dump-after=infer-accesses %s | FileCheck %s --check-prefix=COLLECT
// RUN: %wash --dump-after=find-neighbour-distances %s | FileCheck %s --check-prefix=DIST
// RUN: %wash --dump-after=find-always-writes %s | FileCheck %s --check-prefix=ALWAYS
// RUN: %wash --dump-after=summarise-accesses %s | FileCheck %s --check-prefix=SETS
// RUN: %wash --dump-after=resolve-fields %s 2>/dev/null | FileCheck %s --check-prefix=FIELDS
// RUN: %wash --dump-after=compute-liveness %s 2>/dev/null | FileCheck %s --check-prefix=LIVE
// RUN: %wash --dump-after=find-hazards %s 2>/dev/null | FileCheck %s --check-prefix=HAZARDS
// RUN: %wash --dump-after=plan-neighbour-search %s 2>/dev/null | FileCheck %s --check-prefix=SEARCH
// RUN: %wash --dump-after=plan-neighbour-distances %s 2>/dev/null | FileCheck %s --check-prefix=SEARCH
// RUN: %wash --dump-after=plan-search-reorder %s 2>/dev/null | FileCheck %s --check-prefix=REORDER
// RUN: %wash --dump-model %s > %t.model 2>/dev/null
// RUN: %wash --dump-after=plan-hoists %s > %t.last 2>/dev/null
// RUN: diff %t.model %t.last
// It wins over --dump-model, and -o is ignored as with --dump-model.
// RUN: rm -rf %t.dir
// RUN: %wash --dump-model --dump-after=collect-simulation %s -o %t.dir | FileCheck %s --check-prefix=COLLECT
// RUN: not ls %t.dir
// Warnings of the passes that ran, and only those, are reported.
// RUN: %wash --dump-after=summarise-accesses %s 2> %t.err > /dev/null
// RUN: count 0 < %t.err
// RUN: %wash --dump-after=resolve-fields %s 2> %t.err > /dev/null
// RUN: FileCheck %s --check-prefix=WARN < %t.err
//
// RUN: %wash --dump-after=help | FileCheck %s --check-prefix=LIST --match-full-lines
// RUN: %expect_exit 1 %wash --dump-after=nope %s 2>&1 | FileCheck %s --check-prefix=UNKNOWN
// RUN: %wash --help | FileCheck %s --check-prefix=HELP
#include <wash/wash.hpp>
#include <vector>

void Move(wash::Particle &p) { p.set_pos(p.get_pos() + p.get_vel()); }

void Density(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  double d = 0;
  for (const auto &n : ns)
    d += n.get_mass() / (p.get_pos() - n.get_pos()).magnitude();
  p.set_density(d);
}

void Pressure(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  wash::Vec3D v = p.get_vel();
  for (const auto &n : ns)
    v = v + n.get_vel() * n.get_density();
  p.set_vel(v);
  p.set_force_scalar("pressure", v.magnitude());
}

int main() {
  wash::set_influence_radius(0.5);
  wash::add_update_kernel(&Move);
  wash::add_force_kernel(&Density);
  wash::add_force_kernel(&Pressure);
  wash::start();
}

// DIM:      dimension: 3
// DIM-NEXT: influence-radius: unset
// DIM:      fields
// DIM-NEXT: kernels
// DIM-NEXT: neighbour-searches
// DIM-NEXT: rewritten-after-search: -
// DIM-NEXT: neighbour-distances: none

// COLLECT:      dimension: 3
// COLLECT-NEXT: influence-radius: 0.5 @
// COLLECT:      starts: yes
// COLLECT-NEXT: fields
// COLLECT-NEXT: kernels
// COLLECT-NEXT:   0: update Move @
// COLLECT-NEXT:     own-reads: -
// COLLECT-NEXT:     own-writes: -
// COLLECT-NEXT:     always-writes: -
// COLLECT-NEXT:   1: force Density @
// COLLECT:        2: force Pressure @
// COLLECT:          search: -1
// COLLECT:      neighbour-searches
// COLLECT-NEXT: rewritten-after-search: -
// COLLECT-NEXT: neighbour-distances: none

// DIST:      0: update Move @
// DIST-NEXT:   own-reads: -
// DIST-NEXT:   own-writes: -
// DIST-NEXT:   always-writes: -
// DIST:      neighbour-distances: kept by the search
// DIST-NEXT:   Density @{{[0-9]+:[0-9]+}}: ns.distance(n) for p

// ALWAYS:      0: update Move @
// ALWAYS-NEXT:   own-reads: -
// ALWAYS-NEXT:   own-writes: -
// ALWAYS-NEXT:   always-writes: pos
// ALWAYS:      2: force Pressure @
// ALWAYS-NEXT:   own-reads: -
// ALWAYS-NEXT:   own-writes: -
// ALWAYS-NEXT:   always-writes: pressure vel

// Before resolveFields the sets list their names, in name order.
// SETS:      fields
// SETS-NEXT: kernels
// SETS-NEXT:   0: update Move @
// SETS-NEXT:     own-reads: pos vel
// SETS-NEXT:     own-writes: pos
// SETS:        2: force Pressure @
// SETS-NEXT:     own-reads: vel
// SETS-NEXT:     own-writes: pressure vel
// SETS-NEXT:     always-writes: pressure vel
// SETS-NEXT:     neighbour-reads: density vel
// SETS-NEXT:     hazards: -

// Liveness is not computed yet: every field reads dead.
// FIELDS:      fields
// FIELDS-NEXT:   id: builtin scalar dead read-only
// FIELDS-NEXT:   pos: builtin vector3 dead
// FIELDS:        pressure: created scalar dead @
// FIELDS-NEXT: kernels
// FIELDS:        2: force Pressure @
// FIELDS-NEXT:     own-reads: vel
// FIELDS-NEXT:     own-writes: vel pressure

// LIVE:      id: builtin scalar live read-only
// LIVE:      acc: builtin vector3 dead
// LIVE:      pressure: created scalar live output-only @
// LIVE:      2: force Pressure @
// LIVE:        hazards: -

// HAZARDS:      2: force Pressure @
// HAZARDS:        hazards: vel
// HAZARDS-NEXT:   search: -1
// HAZARDS-NEXT:   halo: -
// HAZARDS:      neighbour-searches
// HAZARDS-NEXT: rewritten-after-search: -

// SEARCH:      2: force Pressure @
// SEARCH:        search: 0
// SEARCH-NEXT:   halo: -
// SEARCH-NEXT:   halo-exchange: -
// SEARCH-NEXT: neighbour-searches
// SEARCH-NEXT:   0: Density Pressure
// SEARCH-NEXT: rewritten-after-search: -
// SEARCH-NEXT: neighbour-distances: kept by the search

// REORDER:      2: force Pressure @
// REORDER:        halo: -
// REORDER:      rewritten-after-search: density pressure

// WARN: warning: {{.*}}'pressure'

// LIST:      detect-dimension
// LIST-NEXT: collect-simulation
// LIST-NEXT: check-variables
// LIST-NEXT: infer-accesses
// LIST-NEXT: find-neighbour-distances
// LIST-NEXT: find-hoistable
// LIST-NEXT: find-always-writes
// LIST-NEXT: summarise-accesses
// LIST-NEXT: resolve-fields
// LIST-NEXT: compute-liveness
// LIST-NEXT: check-force-uses
// LIST-NEXT: find-hazards
// LIST-NEXT: plan-neighbour-search
// LIST-NEXT: plan-neighbour-distances
// LIST-NEXT: plan-search-reorder
// LIST-NEXT: plan-halos
// LIST-NEXT: plan-hoists
// LIST-NOT:  {{.}}

// UNKNOWN: wash: error: unknown pass 'nope'; passes are: detect-dimension, collect-simulation, check-variables, infer-accesses, find-neighbour-distances, find-hoistable, find-always-writes, summarise-accesses, resolve-fields, compute-liveness, check-force-uses, find-hazards, plan-neighbour-search, plan-neighbour-distances, plan-search-reorder, plan-halos, plan-hoists{{$}}

// HELP: --dump-after=<pass> {{ *}}- Print the model right after the named pass and stop ('help' lists them)
