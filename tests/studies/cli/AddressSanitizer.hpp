#pragma once
// GRANWAVE_ADDRESS_SANITIZER: 1 in an AddressSanitizer build, whichever compiler made it (GCC
// defines __SANITIZE_ADDRESS__, clang answers __has_feature), else 0.
#if defined(__SANITIZE_ADDRESS__)
#define GRANWAVE_ADDRESS_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define GRANWAVE_ADDRESS_SANITIZER 1
#endif
#endif
#ifndef GRANWAVE_ADDRESS_SANITIZER
#define GRANWAVE_ADDRESS_SANITIZER 0
#endif
