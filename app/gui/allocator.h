// The C library's allocator tuned for the GUI thread's latency (glibc): its "fast bins" keep
// small freed blocks unmerged until a large block is freed, which then merges them all at
// once. At a re-run's start after a riser run, freeing the 3D view's surface points merged that
// backlog on the GUI thread for 130 to 150 ms (measured with perf; docs/benchmarks.md). Without
// fast bins small blocks are merged as they are freed (thread caches still serve most of them).
// Large blocks are mapped from the system, so that a run's memory goes back to it when freed.
#pragma once

namespace sonarcarve::gui {

/// Call once at start, before the window exists. No effect with another C library.
void tuneAllocatorForLatency();

}  // namespace sonarcarve::gui
