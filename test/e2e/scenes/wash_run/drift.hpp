// The drift's speed, in a header of the scene's own: wash run's test edits it.
#pragma once

constexpr double DriftSpeed = 0.5;
