// The io library's copy of retina/vector_clones.hpp (io, retina and glare
// stand alone, so each library has its own): loops compiled for AVX-512
// (x86-64-v4) and AVX2 beside the baseline, chosen when the program starts, none
// fusing a multiply and an add (-ffp-contract=off), so every version gives
// the same bytes. tests/vector_clones_test.cpp holds the definitions equal.
#pragma once

#ifndef EYESTREAM_VECTOR_CLONES
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 12
#define EYESTREAM_VECTOR_CLONES __attribute__((target_clones("arch=x86-64-v4", "avx2", "default")))
#elif defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)  // (x86-64-v4 in target_clones: GCC 12 on)
#define EYESTREAM_VECTOR_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define EYESTREAM_VECTOR_CLONES
#endif
#endif
