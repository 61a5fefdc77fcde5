#include "studies/particle_run/OutsideFailure.hpp"

#include <new>
#include <system_error>

#include "h5/H5Error.hpp"
#include "studies/run_files/RunCheckpoint.hpp"

namespace granwave {

bool isOutsideFailure(const std::exception& e) {
  // system_error covers filesystem_error and failed writes of text files (errno); bad_alloc
  // is this machine's memory, not the scene's physics: neither is a result worth caching.
  return dynamic_cast<const CheckpointError*>(&e) || dynamic_cast<const h5::H5Error*>(&e) ||
         dynamic_cast<const std::system_error*>(&e) || dynamic_cast<const std::bad_alloc*>(&e);
}

}  // namespace granwave
