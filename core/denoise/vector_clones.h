#pragma once
// The denoiser's hot loops compiled twice on x86-64, for the baseline (SSE2, 4 floats a vector)
// and for x86-64-v3 (AVX2 and FMA, 8 floats), the one the CPU runs chosen once at load time
// (GCC's target_clones). The build targets the baseline so that the binary runs everywhere; the
// loops here are what a denoised frame costs, and they gain about half again their speed.
// Elsewhere the attribute is empty.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define WOVEN_VECTOR_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define WOVEN_VECTOR_CLONES
#endif
