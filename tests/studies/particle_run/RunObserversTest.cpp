// The centre-of-mass series a particle run keeps for its summary survives a checkpoint: saved
// and restored into a fresh observer, it goes on as the observer that saw the whole run.
#include <gtest/gtest.h>

#include "h5/File.hpp"
#include "studies/particle_run/RunObservers.hpp"
#include "tests/h5/ScratchDir.hpp"

namespace granwave {

TEST(RunObservers, CenterOfMassSeriesRestoredFromACheckpointContinuesTheSameSeries) {
  testing::ScratchDir dir;
  auto record = [](double z) {
    Snapshot s;
    s.obs.center_of_mass_height = z;
    return s;
  };
  CenterOfMassSeries whole, first, second;
  for (double z : {0.004, 0.005, 0.0045}) {
    whole.observe(record(z));
    first.observe(record(z));
  }
  {
    h5::File f = h5::File::create(dir.file("c.h5"));
    first.saveState(f, "/com");
    f.close();
  }
  second.restoreState(h5::File::openReadOnly(dir.file("c.h5")), "/com");
  for (double z : {0.0041, 0.0052}) {
    whole.observe(record(z));
    second.observe(record(z));
  }
  EXPECT_EQ(second.height, whole.height);
}

}  // namespace granwave
