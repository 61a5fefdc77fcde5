#pragma once
// The checks every command applies to its options at parse time (exit 2, one line): input
// files are regular files (files/OutputPath.hpp says why), numbers are finite (CLI11's range
// checks let NaN through, since every comparison with NaN is false).
#include <CLI/CLI.hpp>
#include <string>

namespace granwave {

// An existing regular file (symbolic links followed); refuses FIFOs, devices, directories.
CLI::Validator regularInputFile();
// A number that is not NaN or infinite; combine with a range check (`&`).
CLI::Validator finiteNumber();
// A number > bound (>= bound if inclusive); the message says so ("must be > 0"), where
// CLI11's PositiveNumber and Range quote the largest double in full.
CLI::Validator numberAbove(double bound, bool inclusive);
// "auto" or a whole number in [lo, hi].
CLI::Validator autoOrWholeNumber(int lo, int hi);
// A value the user gave, quoted for a message: cut after 60 characters (a megabyte of
// --set value is not echoed back).
std::string quotedValue(const std::string& text);

}  // namespace granwave
