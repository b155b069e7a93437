#pragma once
// Memory a recording process has freed but the allocator still holds.

namespace lmc::devices {

// Hands pages the allocator holds free back to the system (glibc's malloc_trim; nothing elsewhere).
// Called once a trial has ended: a burst of work (the live fusion behind, a processing job) leaves
// freed pages in the threads' arenas, and without this an hour-long session's resident memory
// keeps the highest burst's size although the memory it uses stays flat.
void return_freed_memory();

// The opposite policy, for a batch that allocates and frees the same large buffers trial after
// trial (`lmc process`): freed memory stays in the process for the next trial instead of going back
// to the system and being faulted in and zeroed again. Both of glibc's limits must be set: setting
// either alone stops glibc adapting the other, and the system time grew instead (80-trial subject:
// 0.8 s of system time by default, 2.2–2.6 s with one limit, 0.3–0.4 s with both).
void keep_freed_memory_for_reuse();

}  // namespace lmc::devices
