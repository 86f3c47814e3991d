//===- DriverParts.h - the pieces of the generated driver -------*- C++ -*-===//
//
// Text of the driver's pieces, each against the backend type's interface
// (`backend.owned()`, `backend.forEachParticleChecked(...)`, ...) and the run
// (`run`). Clang-free.
//
//===----------------------------------------------------------------------===//
#pragma once

#include "wash/translator/Emit/CodePlan.h"
#include "wash/translator/Model.h"

#include <ostream>
#include <string>
#include <vector>

namespace wash::tr {

/// S as a C++ string literal: a variable name may hold any character.
std::string stringLiteral(const std::string &S);

/// `Translation translated{...};`: what the program was translated for, every
/// member named.
std::string translationText(const CodePlan &Plan, const std::string &Program = "");

/// What a checkpoint must have been written by (Translation::program): the
/// kernels in order and the stored columns, never the backend, so that every
/// backend's program restarts every other's checkpoints.
std::string programIdentityText(const Model &M, const CodePlan &Plan);

/// `checkpointColumns`: calls f(name, column) for every stored column.
void emitCheckpointColumns(std::ostream &OS, const CodePlan &Plan);

/// `particleBytes`: the size of one particle in the stored columns.
void emitParticleBytes(std::ostream &OS, const CodePlan &Plan);

/// `create_particle`: appends one particle to every column, with the id the
/// backend gives (a distributed backend may keep the row only until the next).
void emitCreateParticle(std::ostream &OS, const CodePlan &Plan);

/// The FrameBuilder calls of `frame()`, in output order (`f` is the builder).
void emitFrameColumns(std::ostream &OS, const CodePlan &Plan);

/// `run.checkFinite(...)` for every stored field K writes, over the real
/// particles, naming the first culprit.
void emitFiniteChecks(std::ostream &OS, const Kernel &K, const CodePlan &Plan,
                      const std::string &Step, const std::string &Indent);

/// The particle loop of kernel K (the KernelIndex-th), calling `Callee` for
/// `self` (and its neighbour list, for a force kernel). What the kernel writes
/// is tested for finiteness in the loop, right after each call; only if a
/// value is not, emitFiniteChecks' scan names the culprit. Positions are
/// wrapped (periodic axes) in between, as before a scan.
void emitParticleLoop(std::ostream &OS, const Kernel &K, unsigned KernelIndex, const CodePlan &Plan,
                      const std::string &Callee);

/// After a kernel that writes pos: wrap the real particles' positions on
/// periodic axes.
void emitWrap(std::ostream &OS, const Kernel &K, const std::string &Indent);

/// `[](auto send) { send(P.a); send(P.b); }`: a visitor of the given columns.
std::string columnsVisitor(const CodePlan &Plan, const std::vector<std::string> &Fields);

/// `a, b and c`, for comments.
std::string fieldList(const std::vector<std::string> &Fields);

/// A reduction kernel: every real particle's value, then the backend's
/// reduction in id order into its variable.
void emitReduction(std::ostream &OS, const Kernel &K, const CodePlan &Plan,
                   const std::string &Callee);

/// `// Name: force kernel, new neighbour search` and the like.
std::string kernelComment(const Model &M, unsigned K);

/// The SearchGeometry of a new search before kernel K: the influence radius,
/// or from the smoothing lengths (Backend::combineMax joins processes' maxima).
std::string searchGeometryText(const CodePlan &Plan, const Kernel &K);

/// Under the smoothing-length rule, `, <callable h(row)>` for the backend's
/// search (a distributed halo reaches only as far as each particle's pairs);
/// empty under the influence-radius rule.
std::string smoothingLengthAccessor(const CodePlan &Plan);

/// The cell size of the backend's domain decomposition, as a callable the
/// backend calls only if it decomposes: the influence radius, or the largest
/// support radius at the start.
std::string domainCellSizeText(const CodePlan &Plan);

/// Under the smoothing-length rule the search keeps every list in `table`:
/// its declaration, and the line of `search` that builds it (both empty
/// under the influence-radius rule).
std::string neighbourTableDeclaration(const CodePlan &Plan);
std::string neighbourTableBuild(const CodePlan &Plan);

/// The neighbour list of particle `i`: built now, or kept by the search's
/// `table` (smoothing-length rule).
std::string neighbourListText(const CodePlan &Plan, const Kernel &K);
/// The per-type rows of a typed program whose kernels run for one type:
/// declared, and rebuilt after each search and each kernel that sets types.
std::string typeRowsDeclaration(const CodePlan &Plan);
std::string typeRowsRebuild(const CodePlan &Plan, const std::string &Indent);
/// The rows a kernel's loop visits: its type's, or every real particle's ("").
std::string kernelRows(const CodePlan &Plan, const Kernel &K);

/// Before a force kernel: point its neighbour reads of snapshotted fields at
/// the snapshot (copied now) if the kernel writes them, else at the live column.
void emitSnapshots(std::ostream &OS, const Kernel &K, const CodePlan &Plan);

/// Before force kernel K (after its search or refresh): the hoisted
/// expressions it reaches, computed for every row, copies included.
void emitHoistedColumns(std::ostream &OS, const CodePlan &Plan, unsigned K);

} // namespace wash::tr
