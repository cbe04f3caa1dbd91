#pragma once

namespace argus::apps {

/// Keeps the memory the program frees mapped for its next allocations (mimalloc's
/// `allow_decommit` off), unless the environment sets MIMALLOC_ALLOW_DECOMMIT itself.
///
/// Why: a distributed run allocates and frees megabytes a tick (each tick's delta, its bytes and
/// CAF's buffers for them, the snapshot rebuilt from it). Freed, mimalloc gave those pages back
/// to the system after 25 ms, a tick or less, and the next tick faulted them in again, zeroed:
/// about 480,000 page faults in the coordinator and 450,000 in the workers of a 20 s run of the
/// large station (bench/RESULTS.md, "Freed memory kept mapped"). A process then holds the peak
/// of what it used; a worker holds its largest run's until it ends. Does nothing in builds
/// without mimalloc (the sanitizers').
void keep_freed_memory_mapped();

}  // namespace argus::apps
