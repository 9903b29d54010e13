#pragma once
// CAPSULA_KERNEL_CLONES: a hot loop marked with it is compiled for AVX-512 (x86-64-v4) and AVX2
// (x86-64-v3) besides the portable baseline, and the widest version the CPU supports is picked
// when the program starts (GCC's target_clones). The build flags stay portable; a loop that is
// to vectorise this way must have no reduction the compiler would need to reassociate.
// Define CAPSULA_NO_KERNEL_CLONES to compile the baseline only.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__) && (__GNUC__ >= 11) &&       \
    !defined(CAPSULA_NO_KERNEL_CLONES)
#define CAPSULA_KERNEL_CLONES __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define CAPSULA_KERNEL_CLONES
#endif
