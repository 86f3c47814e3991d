// Included by emit/multi-file-headers.cpp: particle helpers in a header that
// includes the wash API, and a header one folder deeper.
#pragma once

#include <wash/wash.hpp>

#include "detail/depth.hpp"

bool IsWall(const wash::Particle& p) { return p.get_mass() > 1.5; }

void Damp(wash::Particle& p) {
#ifdef WASH_LINE_PROBE
#warning "line probe"
#endif
  p.set_vel(p.get_vel() * Damping(p));
}
