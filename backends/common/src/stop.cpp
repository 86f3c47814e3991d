// wash::stop() for generated programs: the translator allows it only in void
// kernels, so unlike the reference's it needs no check (see Run::endStep).
#include <wash/backend/program.hpp>

namespace wash {

void stop(CallSite) { detail::runSettings().stopRequested = true; }

} // namespace wash
