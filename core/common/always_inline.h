#pragma once
// LMC_ALWAYS_INLINE: an inline function the compiler must inline, as the visibility kernel's
// bodies need (each is specialised per build inside its caller; visibility_kernel.cpp). GCC and
// Clang spell it [[gnu::always_inline]], MSVC __forceinline; any other compiler gets plain inline.
#if defined(__GNUC__)
#define LMC_ALWAYS_INLINE [[gnu::always_inline]] inline
#elif defined(_MSC_VER)
#define LMC_ALWAYS_INLINE __forceinline
#else
#define LMC_ALWAYS_INLINE inline
#endif
