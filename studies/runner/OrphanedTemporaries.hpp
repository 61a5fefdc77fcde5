#pragma once
// Temporaries of killed processes. Every atomic write of the project goes through a file
// "<target>.tmp-<pid>" or "<target>.<...>.tmp-<pid>" (files/SideFiles.hpp) that is renamed into
// place when complete; a process killed half way cannot delete its own, so the next process that
// writes beside the same target does.
#include <string>

namespace granwave {

// Removes the temporaries of `path` (files/SideFiles.hpp) that processes no longer running (gone,
// or zombies) left beside `path`, so a run cache does not fill with them.
void removeOrphanedTemporaries(const std::string& path);

}  // namespace granwave
