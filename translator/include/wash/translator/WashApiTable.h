//===- WashApiTable.h - lookups over WashApi.def ----------------*- C++ -*-===//
//
// Clang-free: the frontend matches declarations to these entries by name
// (Frontend/WashApi.h), the model passes read the builtin fields directly.
//
//===----------------------------------------------------------------------===//
#pragma once

#include "wash/translator/Model.h"

#include <optional>
#include <span>
#include <string_view>

namespace wash::tr {

/// What a builtin field holds: an id (std::size_t), a double or a vector.
enum class FieldKind { Id, Scalar, Vector };

struct BuiltinField {
  const char *Name;
  FieldKind Kind;
  const char *Getter;
  const char *Setter; ///< "" when the field cannot be set.
  bool AlwaysOutput;  ///< A column of every output format, hence always live.
  bool Created;       ///< wash::create_particle sets it.

  bool settable() const { return *Setter != '\0'; }
  /// How the model stores it: an id is a scalar.
  ForceKind storage() const {
    return Kind == FieldKind::Vector ? ForceKind::Vector : ForceKind::Scalar;
  }
};

/// The builtin fields in dump order.
std::span<const BuiltinField> builtinFields();
const BuiltinField *builtinField(std::string_view Name);

/// The field of a typed simulation holding each particle's type (the index
/// of its type in add_particle_type order): is_type reads it, set_type writes it.
inline constexpr const char *TypeField = "type";

/// A wash::Particle member function: a builtin field's getter or setter, a
/// force accessor (Field null: the force is named by the first argument), or
/// a type accessor (IsType: the type is named by the first argument).
struct ParticleAccessor {
  const char *Method;
  const BuiltinField *Field;
  Mode How;
  ForceKind Kind; ///< The value's kind: scalar or vector (an id reads as scalar).
  bool IsType = false;

  bool isForce() const { return Field == nullptr && !IsType; }
  /// The getter of builtin field Name.
  bool reads(std::string_view Name) const;
};

/// Every accessor: the builtin fields' getters and setters, then the forces'.
std::span<const ParticleAccessor> particleAccessors();
std::optional<ParticleAccessor> decodeAccessor(std::string_view Method);

/// The API's free functions; the enumerators are spelled as the functions.
enum class ApiCall {
#define WASH_CALL(Name, Use, Lowering, MinArgs) Name,
#include "wash/translator/WashApi.def"
};

/// Where a call may be and what wash reads from it (see WashApi.def).
enum class CallUse { Main, MainOnce, Anywhere };
/// What the generated code makes of a call.
enum class CallLowering { Drop, Keep, Generated };

struct ApiCallInfo {
  ApiCall Id;
  const char *Name;
  CallUse Use;
  CallLowering Lowering;
  unsigned MinArgs;                 ///< Arguments without a default.
  std::optional<KernelKind> Kernel; ///< The kind of kernel it registers.

  /// main configures or registers with it (the frontend walks main for it).
  bool readFromMain() const { return Use != CallUse::Anywhere; }
};

/// The reduction target that is the time step (wash::get_time_step), not a
/// variable: wash/detail/sim_time.hpp's timeStepTarget.
inline constexpr std::string_view TimeStepTarget = "time_step";

std::span<const ApiCallInfo> apiCalls();
const ApiCallInfo *apiCall(std::string_view Name);
const ApiCallInfo &apiCall(ApiCall Id);

} // namespace wash::tr
