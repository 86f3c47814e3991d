//===- ForceUses.cpp ------------------------------------------------------===//
#include "wash/translator/Analysis/ForceUses.h"
#include "wash/translator/Names.h"

#include <algorithm>
#include <set>

namespace wash::tr {
namespace {

struct Use {
  bool Read = false, Written = false;
};

Use useOf(const std::string &Name, const std::vector<Kernel> &Kernels) {
  Use U;
  for (const Kernel &K : Kernels) {
    U.Read |= K.OwnReads.count(Name) || K.NeighbourReads.count(Name);
    U.Written |= K.OwnWrites.count(Name) > 0;
  }
  return U;
}

SourcePos firstAccess(const std::string &Name, Mode How, const std::vector<Kernel> &Kernels) {
  for (const Kernel &K : Kernels)
    for (const Access &A : K.Accesses)
      if (A.Kind && A.Field == Name && A.How == How)
        return A.Pos;
  return {};
}

const Field *named(const std::vector<Field> &Fields, const std::string &Name) {
  auto It = std::find_if(Fields.begin(), Fields.end(), [&](const Field &F) {
    return F.Origin != FieldOrigin::Builtin && F.Name == Name;
  });
  return It == Fields.end() ? nullptr : &*It;
}

} // namespace

std::vector<Finding> checkForceUses(const std::vector<Field> &Fields,
                                    const std::vector<Kernel> &Kernels) {
  // What a misspelt name may have meant: forces that hold a value (registered
  // forces are meant to, written ones do) for a read; for a write, forces
  // read and written elsewhere (one read and never written is the misspelt
  // one, and has its error).
  std::vector<std::string> Meant, ReadNames;
  std::vector<const Field *> Forces;
  for (const Field &F : Fields) {
    if (F.Origin == FieldOrigin::Builtin)
      continue;
    Forces.push_back(&F);
    Use U = useOf(F.Name, Kernels);
    if (F.Origin == FieldOrigin::Registered || U.Written)
      Meant.push_back(F.Name);
    if (U.Read && U.Written)
      ReadNames.push_back(F.Name);
  }

  std::vector<Finding> Findings;
  for (const Field *F : Forces) {
    Use U = useOf(F->Name, Kernels);
    if (U.Read && !U.Written) {
      SourcePos At = firstAccess(F->Name, Mode::Read, Kernels);
      std::optional<std::string> Close = closestName(F->Name, Meant);
      if (!Close) {
        Findings.push_back({DiagId::ForceNeverWritten, At, {F->Name}, {}});
        continue;
      }
      Finding R{DiagId::ForceNeverWrittenSuggest, At, {F->Name, *Close}, {}};
      if (const Field *G = named(Fields, *Close); G && G->Origin == FieldOrigin::Registered)
        R.Notes.push_back({DiagId::NoteRegisteredHere, G->Pos, {G->Name}, {}});
      Findings.push_back(R);
    } else if (U.Written && !U.Read) {
      if (std::optional<std::string> Close = closestName(F->Name, ReadNames))
        Findings.push_back({DiagId::ForceNeverRead,
                            firstAccess(F->Name, Mode::Write, Kernels),
                            {F->Name, *Close},
                            {}});
    }
  }
  return Findings;
}

std::vector<Finding> checkForceLimit(const std::vector<ForceRegistration> &Forces,
                                     const std::vector<Kernel> &Kernels) {
  std::set<std::string> Names;
  std::vector<Finding> Out;
  auto Count = [&](const std::string &Name, const SourcePos &Pos) {
    if (Names.insert(Name).second && Names.size() == MaxForces + 1)
      Out.push_back({DiagId::ForceLimit, Pos, {Name, std::to_string(MaxForces)}, {}});
  };
  for (const ForceRegistration &F : Forces)
    Count(F.Name, F.Pos);
  for (const Kernel &K : Kernels)
    for (const Access &A : K.Accesses)
      if (A.Kind)
        Count(A.Field, A.Pos);
  return Out;
}

} // namespace wash::tr
