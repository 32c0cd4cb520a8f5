#include "allocator.h"

#include <cstdlib>  // defines __GLIBC__ with the GNU C library

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace sonarcarve::gui {

void tuneAllocatorForLatency() {
#if defined(__GLIBC__)
  mallopt(M_MXFAST, 0);  // no fast bins
#endif
}

}  // namespace sonarcarve::gui
