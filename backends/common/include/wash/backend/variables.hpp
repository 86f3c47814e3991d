//===- wash/backend/variables.hpp - global variables without a lookup -*- C++ -*-===//
//
// `wash::get_variable("dt")` finds "dt" in a map of strings, which in a
// per-particle helper costs more than the arithmetic around it. The translator
// knows the name, so generated code passes a slot instead
// (`wash::get_variable(wash_gen::var_dt)`, docs/backends.md), which start()
// binds to the variable's value in the runtime's store: the very double the
// map lookup returns. Every write (set_variable in main, init and void
// kernels, reductions, on every MPI rank) goes to that double, so a read sees
// the same bits with nothing to keep in sync, and costs two loads.
//
//===----------------------------------------------------------------------===//
#pragma once

#include <wash/detail/variables.hpp>
#include <wash/settings.hpp>

#include <cstddef>
#include <initializer_list>
#include <wash/call_site.hpp>
#include <string>

namespace wash::backend {

/// A variable the generated code reads: its name (which may hold any byte)
/// and, once bound, where the store keeps its value.
struct VariableSlot {
  const char *name;
  std::size_t length;
  const double *value = nullptr;
};

/// Binds each slot whose variable main has added. The store's entries are
/// std::map nodes, never erased: the addresses hold for the whole run. A slot
/// left unbound (a variable never added) reads through get_variable(name),
/// which reports the error where the reference does.
inline void bindVariables(std::initializer_list<VariableSlot *> slots) {
  for (VariableSlot *slot : slots) {
    auto it = detail::variables().find(std::string(slot->name, slot->length));
    slot->value = it == detail::variables().end() ? nullptr : &it->second;
  }
}

} // namespace wash::backend

namespace wash {

/// get_variable(name) for the slot of that name (see above).
inline double get_variable(const backend::VariableSlot &slot,
                           CallSite loc = CallSite::current()) {
  if (slot.value) [[likely]]
    return *slot.value;
  return get_variable(std::string(slot.name, slot.length), loc);
}

} // namespace wash
