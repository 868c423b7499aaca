#pragma once
// Whether this binary is built with AddressSanitizer: its allocator replaces operator new and its
// instrumentation slows the code several times, so speed and allocation-count checks do not apply.

namespace sdlqr::testing {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kSanitizedBuild = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kSanitizedBuild = true;
#else
inline constexpr bool kSanitizedBuild = false;
#endif
#else
inline constexpr bool kSanitizedBuild = false;
#endif

}  // namespace sdlqr::testing
