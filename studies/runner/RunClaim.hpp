#pragma once
// The right to make one run of a shared cache: an exclusive flock(2) on "<stem>.claim", held
// by the study that makes the run from before it writes the run's scene until its record is
// stored. Studies sharing a cache (at once, on one machine or on a file system whose locks
// reach every client, as NFSv4's do) thus never make the same run twice at once: the second
// waits for the claim and then reuses the first one's record. The kernel drops the lock when
// its holder dies (even by SIGKILL), so a killed study never blocks another. The claim file
// itself stays (an empty file): unlinking it would let a waiter lock a name no one else sees.
#include <string>

namespace granwave {

class RunClaim {
 public:
  RunClaim() = default;
  // Tries once, without waiting; held() says whether it was taken. std::system_error if the
  // claim file cannot be created.
  explicit RunClaim(const std::string& stem);
  ~RunClaim();
  RunClaim(RunClaim&& other) noexcept;
  RunClaim& operator=(RunClaim&& other) noexcept;
  RunClaim(const RunClaim&) = delete;
  RunClaim& operator=(const RunClaim&) = delete;

  bool held() const { return fd_ >= 0; }
  void release();

 private:
  int fd_ = -1;
};

}  // namespace granwave
