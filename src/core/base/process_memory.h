#pragma once
// The process's resident memory as Linux reports it in /proc/self/status:
// on lavapipe the "device" is this process, so its vertex output and tile
// buffers show here, not in device allocations.
#include <cstdint>

namespace shadelab {

// VmHWM, the peak resident set size in bytes; 0 where /proc is unavailable.
uint64_t peakResidentBytes();
// Sets the peak back to the current resident size (writes 5 to
// /proc/self/clear_refs); false where the kernel does not allow it.
bool resetPeakResident();

}  // namespace shadelab
