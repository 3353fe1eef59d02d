#pragma once
/// Whether this test binary runs under AddressSanitizer (tests/sanitized.sh). The
/// sanitized suite looks for memory and undefined-behaviour errors in the code the plain
/// suite checks for its numbers: a test may then run fewer of the same code paths where
/// more cost only time there (a 1024-segment mesh goes through the 192-segment mesh's
/// code), never check a weaker number.
namespace mmv::testing {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kUnderSanitizers = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kUnderSanitizers = true;
#else
inline constexpr bool kUnderSanitizers = false;
#endif
#else
inline constexpr bool kUnderSanitizers = false;
#endif

}  // namespace mmv::testing
