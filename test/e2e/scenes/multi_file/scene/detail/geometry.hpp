// Depth 2: reached through scene/walls.hpp. A classic header guard.
#ifndef MULTI_FILE_SCENE_DETAIL_GEOMETRY_HPP
#define MULTI_FILE_SCENE_DETAIL_GEOMETRY_HPP

#include <wash/wash.hpp>

constexpr double FloorY = 0.05;
constexpr double H = 0.06;

double HeightAboveFloor(const wash::Particle& p) {
    return p.get_pos().at(1) - FloorY;
}

#endif
