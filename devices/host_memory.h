#pragma once
// Memory a recording process has freed but the allocator still holds.

namespace lmc::devices {

// Hands pages the allocator holds free back to the system (glibc's malloc_trim; nothing elsewhere).
// Called once a trial has ended: a burst of work (the live fusion behind, a processing job) leaves
// freed pages in the threads' arenas, and without this an hour-long session's resident memory
// keeps the highest burst's size although the memory it uses stays flat.
void return_freed_memory();

}  // namespace lmc::devices
