//===- wash/math.hpp - constants simulations use ----------------*- C++ -*-===//
#pragma once

/// pi, for simulations that spell it `PI`.
inline constexpr double PI = 3.14159265358979323846;

/// Time step of an animation at 60 frames per second, split into
/// `iterationsPerFrame` iterations and scaled by `timeScale`.
constexpr double TIME_DELTA(double timeScale, double iterationsPerFrame) {
  return (1.0 / 60.0) / iterationsPerFrame * timeScale;
}
