#include "allocator.h"

#include <cstdlib>  // defines __GLIBC__ with the GNU C library

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace sonarcarve::gui {

void tuneAllocatorForLatency() {
#if defined(__GLIBC__)
  mallopt(M_MXFAST, 0);  // no fast bins
  // Blocks of 1 MiB and more (a map's chunks of 1024 blocks, 2 MiB; the view's point arrays)
  // are mapped from the system and given back when freed. Left to itself glibc raises this
  // threshold after the first such free and keeps later ones in its heap: resident memory then
  // grew by 110 to 140 MB from one riser run to the next.
  mallopt(M_MMAP_THRESHOLD, 1 << 20);
#endif
}

}  // namespace sonarcarve::gui
