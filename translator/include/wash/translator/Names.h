//===- Names.h - what a force name may be, and typo suggestions -*- C++ -*-===//
//
// Clang-free: force names become column names in every output format and
// identifiers in the generated code; the frontend adds the checks that need
// the compiler (keywords, macros) in Frontend/ForceName.h.
//
//===----------------------------------------------------------------------===//
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace wash::tr {

/// Why Name cannot name a force, as the rest of "force name '...' ..." (the
/// checks that need no compiler), or nullopt when it can.
std::optional<std::string> forceNameProblem(std::string_view Name);

/// Name with quotes, backslashes and unprintable bytes escaped, for messages.
std::string escapedName(std::string_view Name);

/// The candidate closest to Name that is close enough to be a likely typo
/// (an edit distance of at most a third of its length, at least 1), or
/// nullopt. Ties go to the earlier candidate; Name itself is never offered.
std::optional<std::string> closestName(std::string_view Name,
                                       const std::vector<std::string> &Candidates);

} // namespace wash::tr
