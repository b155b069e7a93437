#pragma once
// What the CPU can run, asked once: the AVX2 and AVX-512 forms of the hot loops (visibility
// kernel, palm hull, fusion sums) are chosen at run time by these, and each equals its plain form
// bit for bit, so the answer changes only the speed.

namespace lmc {

#if defined(__x86_64__) && defined(__GNUC__)
inline bool cpu_has_avx2() {
  static const bool yes = [] {
    __builtin_cpu_init();  // needed when first used from a static initialiser
    return __builtin_cpu_supports("avx2") != 0;
  }();
  return yes;
}
inline bool cpu_has_avx512() {
  static const bool yes = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx512f") != 0;
  }();
  return yes;
}
#else
inline bool cpu_has_avx2() {
  return false;
}
inline bool cpu_has_avx512() {
  return false;
}
#endif

}  // namespace lmc
