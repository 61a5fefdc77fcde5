#pragma once
// HDF5 form of the engine's state and of snapshots, for checkpoints: every field is stored
// as the exact bits it has in memory (doubles as doubles, counters as integers), so that a
// restored run continues bit-identically. Layout under `group`: one dataset per field,
// indexed by particle (or by snapshot); docs/commands.md ("Checkpoints") lists them.
#include <string>
#include <vector>

#include "h5/File.hpp"
#include "particles/EngineState.hpp"
#include "particles/Snapshot.hpp"

namespace granwave {

void writeEngineState(h5::File& file, const std::string& group, const EngineState& state);
// h5::H5Error naming the file and the dataset if anything is missing or of the wrong shape.
EngineState readEngineState(const h5::File& file, const std::string& group);

void writeSnapshots(h5::File& file, const std::string& group,
                    const std::vector<Snapshot>& snapshots);
std::vector<Snapshot> readSnapshots(const h5::File& file, const std::string& group);

}  // namespace granwave
