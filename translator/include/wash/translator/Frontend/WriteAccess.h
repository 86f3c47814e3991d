//===- WriteAccess.h - what gives write access to storage -------*- C++ -*-===//
//
// For GlobalWrites: which types let a value or parameter change storage it
// does not own, and which library functions only read or hand out access,
// or change state hidden in the library.
//
//===----------------------------------------------------------------------===//
#pragma once

#include "clang/AST/Decl.h"
#include "clang/AST/Type.h"

namespace wash::tr {

/// A value of type T can change storage it does not own: a pointer or
/// reference to non-const, or a class holding one (an iterator, a span, a
/// std::reference_wrapper).
bool holdsMutablePointer(clang::QualType T, unsigned Depth = 0);

/// A const object of type T still gives write access to what it points to:
/// a pointer to non-const, a public pointer member, or a const accessor
/// handing out a non-const reference (an iterator, a span, a smart pointer;
/// not a container, whose const accessors are const too).
bool shallowWhenConst(clang::QualType T, unsigned Depth = 0);

/// A parameter of type T lets the callee change what its argument designates
/// or points to.
bool mayWriteThrough(clang::QualType T);

/// Library calls that hand out access to their argument or object, or only
/// read through what they are given (comparisons, the non-modifying
/// algorithms). What accessors return carries what it points into, so a
/// write through it is still found.
bool isLibraryAccessor(const clang::FunctionDecl *FD);

/// Library functions that change state the program cannot see: the C
/// library's random generators (one hidden seed per process), strtok, and
/// std::random_device. Generators the program owns (rand_r, erand48, the
/// <random> engines) pass their state explicitly and are checked as
/// arguments instead.
bool changesHiddenState(const clang::FunctionDecl *FD);

/// A const member returning a non-const reference or pointer (or a free
/// function): the object refers to what it hands out (an iterator, a span,
/// a smart pointer) rather than owning it (a container).
bool isShallow(const clang::FunctionDecl *FD);

} // namespace wash::tr
