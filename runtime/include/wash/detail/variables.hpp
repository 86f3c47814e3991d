//===- wash/detail/variables.hpp - global variables, shared by every runtime -*- C++ -*-===//
#pragma once

#include <map>
#include <wash/call_site.hpp>
#include <string>

namespace wash::detail {

/// The variables of this program, by name.
std::map<std::string, double> &variables();

/// `file:line:col: error: message` as a UsageError.
[[noreturn]] void usageErrorAt(const CallSite &loc, const std::string &message);

} // namespace wash::detail
