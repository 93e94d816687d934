// SPDX-License-Identifier: MIT
// SCADRAY_FMA_CLONES before a function definition: GCC builds a copy of it for CPUs with FMA
// beside the baseline one and picks between them when the program loads, so a std::fma in it
// is one instruction there instead of a call into libm. Both copies compute the same results:
// fma is exactly rounded either way, and the build's -ffp-contract=off keeps GCC from fusing the
// function's other products and sums in the FMA copy (which it would, even in ISO C++ mode).
// GCC only: Clang refuses to multiversion a function already used above its definition, and
// the Clang builds are the sanitizer and fuzzing ones.
#pragma once

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && \
    !defined(__SANITIZE_ADDRESS__)
#define SCADRAY_FMA_CLONES __attribute__((target_clones("fma", "default")))
#else
#define SCADRAY_FMA_CLONES
#endif
