// The full model of the seed example: kernels in order with their access
// sets, predictedPosition dead, position and viscosity created with warnings,
// exactly vel a hazard in force_kernel, one search shared by the two force
// kernels, whose three loops read the distances that search keeps, and
// which rewrites density, nearDensity, pressure and viscosity before any read;
// the neighbours' pressures are computed once per particle, not per pair.
// RUN: %wash --dump-model %wash_src/examples/ca_fluid_sim/ca_fluid_sim.cpp > %t.out 2> %t.err
// RUN: FileCheck %s --match-full-lines --strict-whitespace < %t.out
// RUN: FileCheck %s --check-prefix=WARN < %t.err

//      CHECK:simulation
// CHECK-NEXT:  precision: double
// CHECK-NEXT:  dimension: 2
// CHECK-NEXT:  influence-radius: 0.35 @83:32
// CHECK-NEXT:  smoothing-length-support: unset
// CHECK-NEXT:  max-iterations: 1000 @110:30
// CHECK-NEXT:  simulation-name: runtime argv[1] @87:35 "serial_test" @95:35
// CHECK-NEXT:  output-file-name: runtime argv[2] @90:40 runtime argv[1] @92:40
// CHECK-NEXT:  starts: yes
// CHECK-NEXT:fields
// CHECK-NEXT:  id: builtin scalar live read-only
// CHECK-NEXT:  pos: builtin vector2 live
// CHECK-NEXT:  vel: builtin vector2 live
// CHECK-NEXT:  acc: builtin vector2 dead
// CHECK-NEXT:  density: builtin scalar live
// CHECK-NEXT:  mass: builtin scalar live output-only
// CHECK-NEXT:  smoothing_length: builtin scalar live output-only
// CHECK-NEXT:  nearDensity: registered scalar live @98:21
// CHECK-NEXT:  predictedPosition: registered vector2 dead @99:21
// CHECK-NEXT:  pressure: registered vector2 live output-only @100:21
// CHECK-NEXT:  position: created vector2 live @144:15
// CHECK-NEXT:  viscosity: created vector2 live output-only @222:14
// CHECK-NEXT:kernels
// CHECK-NEXT:  0: init init @102:5
// CHECK-NEXT:    own-reads: -
// CHECK-NEXT:    own-writes: pos vel density mass smoothing_length position
// CHECK-NEXT:  1: update VelocityUpdate @104:5
// CHECK-NEXT:    own-reads: pos vel position
// CHECK-NEXT:    own-writes: pos vel
// CHECK-NEXT:    always-writes: pos vel
// CHECK-NEXT:  2: force CalculateDensity @105:5
// CHECK-NEXT:    own-reads: pos
// CHECK-NEXT:    own-writes: density nearDensity
// CHECK-NEXT:    always-writes: density nearDensity
// CHECK-NEXT:    neighbour-reads: pos
// CHECK-NEXT:    hazards: -
// CHECK-NEXT:    search: 0
// CHECK-NEXT:    halo: pos
// CHECK-NEXT:    halo-exchange (new rows): pos
// CHECK-NEXT:    halo-exchange (rows kept from the previous search): pos
// CHECK-NEXT:  3: force force_kernel @106:5
// CHECK-NEXT:    own-reads: pos vel density nearDensity
// CHECK-NEXT:    own-writes: vel pressure viscosity
// CHECK-NEXT:    always-writes: vel pressure viscosity
// CHECK-NEXT:    neighbour-reads: pos vel density nearDensity
// CHECK-NEXT:    hazards: vel (writes own, reads neighbour)
// CHECK-NEXT:    search: 0
// CHECK-NEXT:    halo: pos vel density nearDensity
// CHECK-NEXT:    halo-exchange: vel density nearDensity
// CHECK-NEXT:    halo-not-sent: pos (not written since they were last sent)
// CHECK-NEXT:  4: update UpdatePositions @107:5
// CHECK-NEXT:    own-reads: vel position
// CHECK-NEXT:    own-writes: position
// CHECK-NEXT:    always-writes: position
// CHECK-NEXT:  5: update HandleCollisions @108:5
// CHECK-NEXT:    own-reads: vel position
// CHECK-NEXT:    own-writes: vel position
// CHECK-NEXT:    always-writes: vel position
// CHECK-NEXT:neighbour-searches
// CHECK-NEXT:  0: CalculateDensity force_kernel
// CHECK-NEXT:rewritten-after-search: density nearDensity pressure viscosity
// CHECK-NEXT:neighbour-distances: kept by the search
// CHECK-NEXT:  CalculateDensity @168:22: neighbours.distance(neighbour) for particle
// CHECK-NEXT:  CalculatePressureForce @191:22: neighbours.distance(neighbour) for particle
// CHECK-NEXT:  CalculateViscosity @218:22: neighbours.distance(neighbour) for particle
// CHECK-NEXT:hoisted-per-neighbour: computed for every row before the kernel, read in its loop
// CHECK-NEXT:  force_kernel:
// CHECK-NEXT:    hoisted_0 = PressureFromDensity(neighbourDensity) @195:36 in CalculatePressureForce: depends only on constants and the fields of 'neighbour': density
// CHECK-NEXT:    hoisted_1 = NearPressureFromDensity(neighbourNearDensity) @196:40 in CalculatePressureForce: depends only on constants and the fields of 'neighbour': nearDensity
//  CHECK-NOT:{{.}}

// WARN: ca_fluid_sim.cpp:144:15: warning: force 'position' is used but never registered; it is created as a vector
// WARN: ca_fluid_sim.cpp:222:14: warning: force 'viscosity' is used but never registered; it is created as a vector
// WARN: ca_fluid_sim.cpp:99:21: warning: force 'predictedPosition' is registered but never read or written; it gets no storage
// WARN: 3 warnings generated.
