//===- DriverParts.h - pieces every generated driver shares -----*- C++ -*-===//
#pragma once

#include "wash/translator/Emit/CodePlan.h"
#include "wash/translator/Model.h"

#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace wash::tr {

/// `create_particle`: appends one particle to every column.
void emitCreateParticle(std::ostream &OS, const CodePlan &Plan);

/// `wash::backend::Translation{...}`: what the program was translated for,
/// every member named.
std::string translationText(const CodePlan &Plan);

/// The FrameBuilder calls of `frame()`, in output order (`f` is the builder).
void emitFrameColumns(std::ostream &OS, const CodePlan &Plan);

/// `run.checkFinite(...)` for every stored field K writes, at the positions
/// the expression Rows names ("images.owned", "halo.owned").
void emitFiniteChecks(std::ostream &OS, const Kernel &K, const CodePlan &Plan,
                      const std::string &Step, const std::string &Rows,
                      const std::string &Indent);

/// The particle loop of kernel K (the KernelIndex-th) over `Rows`, with the
/// forEachParticle of `LoopNamespace`, calling `Callee` for `self` (and its
/// neighbour list, for a force kernel). What the
/// kernel writes is tested for finiteness in the loop, right after each call
/// (no second pass over the columns); only if a value is not, the columns are
/// scanned to name the first culprit, as emitFiniteChecks does. Positions are
/// wrapped (periodic axes) in between, as before a scan.
void emitParticleLoop(std::ostream &OS, const Kernel &K, unsigned KernelIndex, const CodePlan &Plan,
                      const std::string &LoopNamespace, const std::string &Rows,
                      const std::string &Callee);

/// After a kernel that writes pos: wrap the positions of Rows on periodic axes.
void emitWrap(std::ostream &OS, const Kernel &K, const std::string &Rows,
              const std::string &Indent);

/// `[](auto send) { send(P.a); send(P.b); }`: a visitor of the given columns.
std::string columnsVisitor(const CodePlan &Plan, const std::vector<std::string> &Fields);
std::string columnsVisitor(const CodePlan &Plan, const FieldSet &Fields);

/// A reduction kernel: every real particle's value (positions `Rows`, loop
/// `Loop`), then `Reduce(P.id, values, Rows, op)` into its variable.
void emitReduction(std::ostream &OS, const Kernel &K, const std::string &Callee,
                   const std::string &Loop, const std::string &Rows, const std::string &Reduce);

/// The iteration loop: EmitKernel(K) for every non-init kernel, in order, then
/// the end-of-step output.
void emitIterations(std::ostream &OS, const Model &M,
                    const std::function<void(unsigned)> &EmitKernel);

/// `// Name: force kernel, new neighbour search` and the like.
std::string kernelComment(const Model &M, unsigned K);

/// The SearchGeometry of a new search before kernel K: the influence radius,
/// or from the smoothing lengths at `Rows` (GlobalMax combines ranks' maxima).
std::string searchGeometryText(const CodePlan &Plan, const Kernel &K, const std::string &Rows,
                               const std::string &GlobalMax);

/// Under the smoothing-length rule the search keeps every list in `table`:
/// its declaration, and the line of `search` that builds it for `Rows`
/// (both empty under the influence-radius rule).
std::string neighbourTableDeclaration(const CodePlan &Plan);
std::string neighbourTableBuild(const CodePlan &Plan, const std::string &Rows);

/// The neighbour list of particle `i`: built now, or kept by the search's
/// `table` (smoothing-length rule).
std::string neighbourListText(const CodePlan &Plan);

/// Before a force kernel: point neighbour reads of snapshotted fields at the
/// snapshot (copied now) if the kernel writes them, else at the live column.
void emitSnapshots(std::ostream &OS, const Kernel &K, const CodePlan &Plan);

} // namespace wash::tr
