// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file Simd.h
 * @brief Whether the core's SSE2 lane paths are compiled: where the target
 * has SSE2 (every x86-64 does) and BOUNDPARTICLES_NO_SIMD is not defined.
 *
 * Elsewhere (aarch64), or with BOUNDPARTICLES_NO_SIMD (to test those paths
 * on x86-64), each lane path's scalar twin runs instead, with the same bits:
 * every lane path is defined as equal to it.
 */
#ifndef BoundParticles_Simd_h
#define BoundParticles_Simd_h

#if defined(__SSE2__) && !defined(BOUNDPARTICLES_NO_SIMD)
#include <emmintrin.h>
#define BOUNDPARTICLES_SSE2 1
#else
#define BOUNDPARTICLES_SSE2 0
#endif

#endif
