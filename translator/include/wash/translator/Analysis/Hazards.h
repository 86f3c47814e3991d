//===- Hazards.h - fields that need a snapshot ------------------*- C++ -*-===//
#pragma once

#include "wash/translator/Model.h"

namespace wash::tr {

/// A force kernel that writes a field on its own particle and reads the same
/// field on neighbours would see a mix of old and new values once particles
/// run in parallel: such fields (and only those) need a snapshot copy taken
/// before the kernel. Fills Kernel::Hazards. Needs summariseAccesses.
void findHazards(Model &M);

} // namespace wash::tr
