//===- RewriteSource.h - the user's code, with particle accesses lowered -*- C++ -*-===//
//
// The one code-generation pass that needs the AST. The user's kernels and
// helpers are rewritten in place, not re-typeset, so they stay readable:
//  - `p.get_vel()` / `p.set_force_scalar("x", v)` become column accesses
//    (`wash_gen::P.vel[p]`, `wash_gen::P.x[p] = v`), snapshot-aware where needed;
//  - `wash::Particle&` becomes `wash_gen::Self&`, a `const wash::Particle&` or
//    a copy `auto` (a self or a neighbour handle), and
//    `std::vector<wash::Particle>` the backend's neighbour range;
//  - `get_variable("x")` reads the slot `wash_gen::var_x`, not a map;
//  - registration calls become `(void)0`, `wash::start()` the generated
//    driver, `wash::create_particle` the generated one, and the
//    `#include <wash/wash.hpp>` the generated storage header.
// The same holds in every user header the simulation includes (Emit/UserFiles):
// each is rewritten too, and the includes between them name the copies.
//
//===----------------------------------------------------------------------===//
#pragma once

#include "wash/translator/Emit/CodePlan.h"
#include "wash/translator/Frontend/Diagnoser.h"
#include "wash/translator/Frontend/Includes.h"

#include "clang/AST/ASTContext.h"

#include <optional>
#include <string>
#include <vector>

namespace wash::tr {

struct RewrittenFile {
  std::string Original;    ///< The user's file, absolute.
  std::string ProjectPath; ///< Where its copy goes, relative to the project.
  std::string Text;        ///< Rewritten, with the original's line numbers.
};

/// The rewritten main file, then each rewritten header, or nothing after an
/// error (reported through D). `Variables` gets the names of the variables
/// whose reads were given slots (CodePlan::Variables).
std::optional<std::vector<RewrittenFile>> rewriteSource(clang::ASTContext &Ctx,
                                                        const CodePlan &Plan,
                                                        const IncludeDirectives &Includes,
                                                        Diagnoser &D,
                                                        std::vector<std::string> *Variables = nullptr);

} // namespace wash::tr
