#pragma once
// The one exception type of the HDF5 layer. Its message is a single line that names the file
// and, where there is one, the object path, so that a user who passes the wrong file to a
// granwave command learns which file and what is missing without a stack trace.
#include <stdexcept>

namespace granwave::h5 {

class H5Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace granwave::h5
