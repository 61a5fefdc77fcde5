#pragma once
// The checks every command applies to its options at parse time (exit 2, one line): input
// files are regular files (files/OutputPath.hpp says why), numbers are finite (CLI11's range
// checks let NaN through, since every comparison with NaN is false).
#include <CLI/CLI.hpp>

namespace granwave {

// An existing regular file (symbolic links followed); refuses FIFOs, devices, directories.
CLI::Validator regularInputFile();
// A number that is not NaN or infinite; combine with a range check (`&`).
CLI::Validator finiteNumber();

}  // namespace granwave
