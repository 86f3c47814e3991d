// A library header on an -isystem path, which wash does not rewrite.
#pragma once

#include <wash/wash.hpp>

inline double LibraryMass(const wash::Particle& p) { return p.get_mass(); }
