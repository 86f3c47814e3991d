//===- SummariseAccesses.cpp ----------------------------------------------===//
#include "wash/translator/Analysis/SummariseAccesses.h"

namespace wash::tr {

void summariseAccesses(Model &M) {
  for (Kernel &K : M.Kernels) {
    K.OwnReads.clear();
    K.OwnWrites.clear();
    K.NeighbourReads.clear();
    for (const Access &A : K.Accesses) {
      if (A.On == Target::Own)
        (A.How == Mode::Read ? K.OwnReads : K.OwnWrites).insert(A.Field);
      else if (A.How == Mode::Read)
        K.NeighbourReads.insert(A.Field);
      // Neighbour writes are rejected by the frontend and never recorded.
    }
    // Under the smoothing-length rule the search reads h_i for each particle.
    if (K.Kind == KernelKind::Force && M.searchesBySmoothingLength())
      K.OwnReads.insert("smoothing_length");
  }
}

} // namespace wash::tr
