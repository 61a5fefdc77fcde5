#pragma once
// Program version, from the project() call in CMakeLists.txt.
namespace granwave {
inline constexpr const char* kVersion = GRANWAVE_VERSION;
}
