#pragma once
// String types. granwave writes variable-length UTF-8 strings (what h5py writes for Python
// str, so Python tools get str back); it reads both variable- and fixed-length strings,
// since files edited by other tools may hold either.
#include <hdf5.h>

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "h5/Handle.hpp"

namespace granwave::h5 {

// Variable-length UTF-8 string type, for writing (data passed as const char* per element).
Handle utf8StringType(const std::string& file);

// Reads `count` strings stored with `stored_type` by calling `read(memory_type, buffer)`
// (H5Aread or H5Dread). `what` names the object in messages.
std::vector<std::string> readStrings(hid_t stored_type, std::size_t count,
                                     const std::function<herr_t(hid_t, void*)>& read,
                                     const std::string& file, const std::string& what);

}  // namespace granwave::h5
